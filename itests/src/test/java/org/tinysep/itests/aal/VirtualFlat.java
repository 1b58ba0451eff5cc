package org.tinysep.itests.aal;

import java.io.IOException;
import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.Device;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;

/**
 * Plays a script of sensor events in virtual time and records what the platform does, each entry stamped
 * {@code HH:mm:ss} (UTC) with the virtual time: Flat Occupancy changes, Inactivity Recognition state changes, the
 * Light Control commands the simulated light nodes received, and the platform's confirmations of them.
 * <p>
 * Lock-step without timing assumptions (docs/time-sync.md, "wait for the effect"): after each sensor frame it waits
 * until a probe listener — connected to the sensor after Flat Occupancy, Follow Me Light and Inactivity Recognition,
 * so called after them — has heard it; after each frame and each TICK it waits until every light command is
 * answered and confirmed (no light has a pending request). Only then does it send the next TICK.
 */
final class VirtualFlat {

    private static final DateTimeFormatter HMS = DateTimeFormatter.ofPattern("HH:mm:ss").withZone(ZoneOffset.UTC);

    final List<String> occupancy = Collections.synchronizedList(new ArrayList<>());
    final List<String> inactivity = Collections.synchronizedList(new ArrayList<>());
    final List<String> commands = Collections.synchronizedList(new ArrayList<>());
    final List<String> confirmations = Collections.synchronizedList(new ArrayList<>());

    private final SyncPeer sync;
    private final TimeControllerProvider clock;
    private final Instant midnight;
    private final long denseSeconds;
    private final AtomicInteger reports = new AtomicInteger();
    private final List<Device> lightDevices = new ArrayList<>();
    private final List<Connection> connections = new ArrayList<>();
    private Instant now;

    /**
     * @param denseSeconds after every event, TICK every second for this long (covering every grace period and
     *                     leave check the event starts); between such windows, jump straight to the next event
     */
    VirtualFlat(SyncPeer sync, TimeControllerProvider clock, Instant midnight, long denseSeconds) throws IOException {
        this.sync = sync;
        this.clock = clock;
        this.midnight = midnight;
        this.denseSeconds = denseSeconds;
        this.now = midnight;
        sync.tickDone(midnight);
    }

    static String hms(Instant at) {
        return HMS.format(at);
    }

    static String onOff(boolean on) {
        return on ? "on" : "off";
    }

    /** @return the virtual instant of {@code HH:mm:ss} on the test's day */
    Instant at(String hhmmss) {
        return midnight.plusSeconds(LocalTime.parse(hhmmss).toSecondOfDay());
    }

    Instant now() {
        return clock.now();
    }

    void watch(FlatOccupancyProvider flat) {
        connections.add(flat.connect((src, o, at) -> occupancy.add(hms(at) + " " + o)));
    }

    void watch(InactivityRecognitionProvider p) {
        connections.add(p.connect((src, s, at) -> inactivity.add(hms(at) + " " + s)));
    }

    void watch(MovementProvider p) {
        connections.add(p.connect((src, m) -> reports.incrementAndGet()));
    }

    void watch(PetMovementProvider p) {
        connections.add(p.connect((src, m) -> reports.incrementAndGet()));
    }

    void watch(DoorProvider p) {
        connections.add(p.connect((src, s, at) -> reports.incrementAndGet()));
    }

    void watch(SimulatedLight light, SimpleLightProvider p, Device device) {
        lightDevices.add(device);
        connections.add(p.connect((src, on, at) -> confirmations.add(hms(at) + " " + light.label() + " " + onOff(on))));
    }

    /** Waits for the light's first status report (off) and takes it out of the confirmations. */
    void takeFirstReport(SimulatedLight light) {
        String suffix = " " + light.label() + " off";
        await(() -> confirmations.removeIf(c -> c.endsWith(suffix)), light.label() + "'s first report");
    }

    /** Sends one frame from a sensor node and waits until the platform's services have all handled it. */
    void report(AmicaNode node, FlatScript.SensorFrame frame) throws IOException {
        int before = reports.get();
        frame.send(node);
        await(() -> reports.get() > before, "the report of " + node.id() + " to be handled");
        settle();
    }

    static void door(AmicaNode node, boolean open) throws IOException {
        node.send(new ReedSwitchStatus(open));
    }

    /**
     * Plays the script: for each event, TICKs up to its time (every second within {@code denseSeconds} of the
     * previous event, one jump otherwise), then sends its frame; finally TICKs on to {@code end}.
     */
    void play(List<FlatScript.Event> script, Instant end) throws IOException {
        Instant denseUntil = now;
        for (FlatScript.Event e : script) {
            advance(e.at(), denseUntil);
            report(e.node(), e.frame());
            denseUntil = e.at().plusSeconds(denseSeconds);
        }
        advance(end, denseUntil);
    }

    private void advance(Instant to, Instant denseUntil) throws IOException {
        for (Instant t = now.plusSeconds(1); !t.isAfter(to) && !t.isAfter(denseUntil); t = t.plusSeconds(1)) {
            tick(t);
        }
        if (to.isAfter(now)) {
            tick(to);
        }
    }

    void tick(Instant t) throws IOException {
        sync.tickDone(t);
        now = t;
        settle();
    }

    /** Waits until every light command was received, answered and confirmed. */
    void settle() {
        await(() -> commands.size() == confirmations.size() && lightDevices.stream().allMatch(VirtualFlat::idle),
                "every light command answered and confirmed (commands " + commands + ", confirmed " + confirmations
                        + ")");
    }

    private static boolean idle(Device light) {
        String pending = AalTestSupport.parameter(light, "pending");
        return pending == null || pending.isEmpty();
    }

    void close() {
        connections.forEach(Connection::close);
    }

    private static void await(BooleanSupplier condition, String what) {
        long end = System.nanoTime() + 10_000_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > end) {
                throw new AssertionError("timed out after 10 s waiting for " + what);
            }
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError("interrupted waiting for " + what);
            }
        }
    }
}
