package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.tinysep.amica.busradio.base.TestRadio.frame;
import static org.tinysep.amica.busradio.base.TestRadio.keepAlive;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.PacketEntry;

/** The node table and the way out: command framing, routes, offline marking, forgetting removed nodes. */
class AmicaNodesTest {

    private final TestRadio radio = new TestRadio();

    @Test
    void commandsAreFramedFromThePlatformToTheNodeAlongTheRouteItWasLastHeardOn() throws Exception {
        radio.feed(frame(1, 20, keepAlive(AmicaNodeType.DIMMABLE_LIGHT)), "first");
        AmicaBusDevice<String> light = radio.nodes.find(new AmicaAddress(1, 20));
        radio.feed(frame(1, 20, AmicaPayloads.encode(new LightControl(10))), "second");

        light.send(AmicaPayloads.encode(new LightControl(40)));
        light.send(AmicaPayloads.encode(new LightControl(41)));

        assertEquals(List.of("second", "second"), radio.routes);
        AmicaFrame first = AmicaCodec.decode(radio.transmitted.get(0), 0, radio.transmitted.get(0).length);
        AmicaFrame next = AmicaCodec.decode(radio.transmitted.get(1), 0, radio.transmitted.get(1).length);
        assertEquals(AmicaFrame.fromPlatform(new AmicaAddress(1, 20), 0, AmicaPayloads.encode(new LightControl(40))),
                first);
        assertEquals(1, next.sequence());
        assertEquals(2, radio.nodes.sent());
        PacketEntry sent = radio.logs.packets().get(radio.logs.packets().size() - 1);
        assertEquals(Direction.SENT, sent.direction());
        assertEquals("node 1.20 via route second", sent.origin());
        assertEquals("", sent.note());
        assertEquals("route second", parameter(light, "remote"));
    }

    @Test
    void aSentCommandsOriginIsFormattedOncePerNodeAndRoute() {
        radio.feed(frame(1, 20, keepAlive(AmicaNodeType.DIMMABLE_LIGHT)), "first");
        AmicaBusDevice<String> light = radio.nodes.find(new AmicaAddress(1, 20));
        int before = radio.describes;

        for (int i = 0; i < 50; i++) {
            light.send(AmicaPayloads.encode(new LightControl(i)));
        }

        assertEquals(1, radio.describes - before, "routes formatted for 50 commands to one node by one route");
        List<PacketEntry> packets = radio.logs.packets();
        assertSame(packets.get(packets.size() - 1).origin(), packets.get(packets.size() - 2).origin());
        radio.feed(frame(1, 20, AmicaPayloads.encode(new LightControl(10))), "second");
        light.send(AmicaPayloads.encode(new LightControl(40)));
        assertEquals("node 1.20 via route second", radio.logs.packets().get(radio.logs.packets().size() - 1).origin(),
                "a new route is named anew");
    }

    @Test
    void aFailedTransmissionIsCountedAndNotedInThePacketLog() {
        radio.feed(frame(1, 20, keepAlive(AmicaNodeType.HEATER)), "tty");
        radio.failure = "not sent: port closed";

        radio.nodes.find(new AmicaAddress(1, 20)).send(new byte[] {5, 8, 0, 50});

        assertEquals(0, radio.nodes.sent());
        assertEquals(1, radio.nodes.failed());
        assertEquals("not sent: port closed", radio.logs.packets().get(1).note());
    }

    @Test
    void badCommandPayloadsAreRefusedBeforeAnythingIsSent() {
        radio.feed(frame(1, 20, keepAlive(AmicaNodeType.HEATER)), "tty");
        AmicaBusDevice<String> heater = radio.nodes.find(new AmicaAddress(1, 20));
        assertThrows(IllegalArgumentException.class, () -> heater.send(new byte[0]));
        assertThrows(IllegalArgumentException.class, () -> heater.send(new byte[256]));
        assertEquals(List.of(), radio.transmitted);
    }

    @Test
    void offlineNodesComeBackOnlineWithTheirNextPacket() {
        radio.feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)), "tty");
        radio.feed(frame(1, 18, keepAlive(AmicaNodeType.DOOR)), "tty");
        AmicaBusDevice<String> movement = radio.nodes.find(new AmicaAddress(1, 17));
        AmicaBusDevice<String> door = radio.nodes.find(new AmicaAddress(1, 18));
        assertEquals(DeviceStatus.State.ONLINE, movement.status().state());

        radio.nodes.offline("port tty lost");
        assertEquals(new DeviceStatus(DeviceStatus.State.OFFLINE, "port tty lost", TestRadio.T0), movement.status());
        assertEquals(DeviceStatus.State.OFFLINE, door.status().state());

        radio.feed(frame(1, 17, AmicaPayloads.encode(new MotionDetection(true))), "tty");
        assertEquals(DeviceStatus.State.ONLINE, movement.status().state());
        assertEquals(DeviceStatus.State.OFFLINE, door.status().state());
        assertEquals(2, radio.nodes.size(), "offline devices are kept");
    }

    @Test
    void aForgottenNodeIsCreatedAnewByItsNextKeepAlive() {
        radio.feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)), "tty");
        AmicaBusDevice<String> old = radio.nodes.find(new AmicaAddress(1, 17));
        radio.nodes.forget(old);
        assertNull(radio.nodes.find(new AmicaAddress(1, 17)));

        radio.feed(frame(1, 17, AmicaPayloads.encode(new MotionDetection(true))), "tty"); // unknown again
        assertNull(radio.nodes.find(new AmicaAddress(1, 17)));
        radio.feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)), "tty");
        AmicaBusDevice<String> renewed = radio.nodes.find(new AmicaAddress(1, 17));
        assertEquals(old.uid(), renewed.uid(), "same node, same UID");
        assertSame(renewed, radio.nodes.all().get(0));
    }

    private static String parameter(AmicaBusDevice<String> device, String key) {
        return device.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}
