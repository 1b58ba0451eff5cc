package org.tinysep.benchmarks;

import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.house.codec.HouseRoom;
import org.tinysep.house.codec.HouseRooms;
import org.tinysep.house.codec.HouseXml;

/**
 * Packet → reaction through Follow Me Light: K rooms, each with a movement node (20.r) and a simple light node
 * (21.r) placed in it. A sample: a motion frame from room r's sensor → the light command "100 %" received at
 * room r's light node. The light node confirms every command with its status report (the thesis actuator model);
 * after {@code graceSeconds} (5) without motion Follow Me Light switches the room's light off again, so the rooms
 * are used in turn, each again only after its light went off.
 */
final class Reaction implements AutoCloseable {

    static final int GRACE_SECONDS = 5;
    private final int rooms;
    private final DatagramChannel sensors;
    private final DatagramChannel lights;
    private final InetSocketAddress radio;
    private final Map<Integer, CompletableFuture<Long>> waiting = new ConcurrentHashMap<>();
    private final Thread reader;

    Reaction(int rooms, int radioPort) throws Exception {
        this.rooms = rooms;
        radio = new InetSocketAddress("127.0.0.1", radioPort);
        sensors = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
        lights = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
        reader = new Thread(this::readCommands, "light-nodes");
        reader.setDaemon(true);
        reader.start();
    }

    /** Writes the house (K rooms), the placements and Follow Me Light's grace into a copy before its start. */
    static void prepare(Bench.Installed inst, int rooms) throws Exception {
        List<HouseRoom> house = new ArrayList<>();
        List<String> placements = new ArrayList<>();
        for (int r = 1; r <= rooms; r++) {
            String name = String.format("R%02d", r);
            house.add(new HouseRoom(String.format("b1000000-0000-4000-8000-%012d", r), name, "Room", List.of()));
            placements.add("20." + r + "=" + name);
            placements.add("21." + r + "=" + name);
        }
        Path file = inst.var().resolve("house.xml");
        Files.write(file, HouseXml.toBytes(new HouseRooms(house)));
        Path etc = inst.home().resolve("etc");
        Files.writeString(etc.resolve("org.tinysep.houseinformation.cfg"), "file=" + file + "\n");
        Files.writeString(etc.resolve("org.tinysep.houseinformation.placement.cfg"),
                "placements=" + String.join(", ", placements) + "\n");
        Files.writeString(etc.resolve("org.tinysep.followmelight.cfg"), "graceSeconds=" + GRACE_SECONDS + "\n");
    }

    /** Announces the K sensors and K lights (lights report off) and waits for their devices. */
    void announce(MeasuredPlatform p) throws Exception {
        int movement = AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT));
        int light = AmicaNodeType.productId(List.of(AmicaNodeType.SIMPLE_LIGHT));
        for (int r = 1; r <= rooms; r++) {
            send(sensors, new AmicaAddress(20, r), new KeepAlive(0, 3000, 0, movement, 1));
            send(lights, new AmicaAddress(21, r), new KeepAlive(0, 3000, 0, light, 1));
            send(lights, new AmicaAddress(21, r), new LightControl(0));
        }
        Bench.awaitDevices(p, "AmicaSimpleLight", rooms, Duration.ofMinutes(2));
        Bench.awaitDevices(p, "AmicaMovement", rooms, Duration.ofMinutes(2));
        Bench.sleep(2); // placements and Follow Me Light's connections follow the devices
    }

    /**
     * @return sorted latencies in µs of the samples answered within 2 s; {@code missed} gets the others' count
     */
    double[] measure(int samples, long intervalMillis, long[] missed) throws Exception {
        List<Double> us = new ArrayList<>();
        for (int i = 0; i < samples; i++) {
            int room = 1 + i % rooms;
            CompletableFuture<Long> on = new CompletableFuture<>();
            waiting.put(room, on);
            long t0 = System.nanoTime();
            send(sensors, new AmicaAddress(20, room), new MotionDetection(true));
            try {
                us.add((on.get(2, TimeUnit.SECONDS) - t0) / 1e3);
            } catch (java.util.concurrent.TimeoutException e) {
                missed[0]++;
            }
            waiting.remove(room);
            long left = intervalMillis - (System.nanoTime() - t0) / 1_000_000;
            if (left > 0) {
                Thread.sleep(left);
            }
        }
        double[] out = us.stream().mapToDouble(Double::doubleValue).toArray();
        Arrays.sort(out);
        return out;
    }

    private void readCommands() {
        ByteBuffer b = ByteBuffer.allocate(512);
        try {
            while (true) {
                b.clear();
                SocketAddress from = lights.receive(b);
                long at = System.nanoTime();
                AmicaFrame f = AmicaCodec.decode(b.array(), 0, b.position());
                AmicaPayload payload = AmicaPayloads.decode(f.payload());
                if (payload instanceof LightControl c) {
                    if (c.percent() > 0) {
                        CompletableFuture<Long> w = waiting.get(f.destination());
                        if (w != null && f.netgroup() == 21) {
                            w.complete(at);
                        }
                    }
                    // the node does what it was told and reports it: the platform's confirmation
                    send(lights, new AmicaAddress(f.netgroup(), f.destination()), new LightControl(c.percent()));
                }
            }
        } catch (Exception end) {
            // closed
        }
    }

    private void send(DatagramChannel ch, AmicaAddress node, AmicaPayload payload) throws java.io.IOException {
        ch.send(ByteBuffer.wrap(AmicaCodec.encode(AmicaFrame.toPlatform(node, 0, AmicaPayloads.encode(payload)))),
                radio);
    }

    @Override
    public void close() throws Exception {
        sensors.close();
        lights.close();
        reader.join(2_000);
    }
}
