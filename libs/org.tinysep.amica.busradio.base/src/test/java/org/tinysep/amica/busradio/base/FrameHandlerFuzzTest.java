package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.link.frame.testing.TestBytes.concat;
import static org.tinysep.link.frame.testing.TestBytes.flip;
import static org.tinysep.link.frame.testing.TestBytes.insert;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.Fuzz;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.PacketEntry;

/**
 * The base frame logic fed random, valid and mutated frames (bit flips, truncations, insertions, garbage around
 * frames; fixed seeds, see {@link Fuzz}): it never throws, logs every input once, counts every rejection under the
 * reason an independent oracle (the protocol library applied by hand) expects, and creates bus devices exactly for
 * the nodes whose valid keep-alive it saw.
 */
class FrameHandlerFuzzTest {

    @Test
    void everyInputIsDeliveredOrCountedUnderItsReason() {
        Map<String, Integer> outcomes = new TreeMap<>();
        Fuzz.forAll(301, 300, r -> {
            List<byte[]> datagrams = datagrams(r);
            TestRadio radio = new TestRadio();
            Set<AmicaAddress> announced = new HashSet<>();
            Map<RejectReason, Long> expected = new EnumMap<>(RejectReason.class);
            long delivered = 0;
            for (byte[] d : datagrams) {
                RejectReason reason = oracle(d, announced);
                outcomes.merge(reason == null ? "delivered" : reason.name(), 1, Integer::sum);
                if (reason == null) {
                    delivered++;
                } else {
                    expected.merge(reason, 1L, Long::sum);
                }
                radio.feed(d, "r");
            }

            List<PacketEntry> packets = radio.logs.packets();
            assertEquals(datagrams.size(), packets.size(), "every input in the packet log");
            assertEquals(datagrams.size(), radio.handler.received());
            for (RejectReason reason : RejectReason.values()) {
                assertEquals(expected.getOrDefault(reason, 0L), radio.rejects.count(reason), reason.name());
            }
            long noted = packets.stream().filter(p -> !p.note().isEmpty()).count();
            assertEquals(radio.rejects.total(), noted, "each rejection noted in the packet log");
            assertTrue(packets.stream().filter(p -> !p.note().isEmpty()).allMatch(
                    p -> Arrays.stream(RejectReason.values()).anyMatch(reason -> p.note().startsWith(reason.name()))));
            assertEquals(announced,
                    radio.nodes.all().stream().map(AmicaBusDevice::address).collect(Collectors.toSet()));
            long devicePackets = radio.nodes.all().stream().mapToLong(d -> Long.parseLong(d.parameters().stream()
                    .filter(p -> p.key().equals("packets")).findFirst().orElseThrow().value())).sum();
            assertEquals(delivered, devicePackets, "every accepted frame reached its bus device");
        });
        // the generators must reach every outcome, or the checks above would prove less than they claim
        for (RejectReason reason : RejectReason.values()) {
            assertTrue(outcomes.getOrDefault(reason.name(), 0) > 0, "never reached " + reason + ": " + outcomes);
        }
        assertTrue(outcomes.getOrDefault("delivered", 0) > 0, "nothing delivered: " + outcomes);
    }

    /** @return the reason the input must be rejected for, or null when it must be delivered */
    private static RejectReason oracle(byte[] d, Set<AmicaAddress> announced) {
        try {
            AmicaFrame f = AmicaCodec.decode(d, 0, d.length);
            AmicaPayload p = AmicaPayloads.decode(f.payload());
            if (p instanceof KeepAlive) {
                announced.add(f.sender());
            } else if (!announced.contains(f.sender())) {
                return RejectReason.UNKNOWN_NODE;
            }
            return null;
        } catch (AmicaProtocolException e) {
            return e.reason();
        }
    }

    /** 0..40 datagrams: valid frames, mutated frames, frames with mutated payloads, garbage (weights 4:4:2:1). */
    private static List<byte[]> datagrams(Random r) {
        List<byte[]> datagrams = new ArrayList<>();
        for (int i = Fuzz.between(r, 0, 40); i > 0; i--) {
            datagrams.add(switch (Fuzz.weighted(r, 4, 4, 2, 1)) {
                case 0 -> validFrame(r);
                case 1 -> mutatedFrame(r);
                case 2 -> frameWithMutatedPayload(r);
                default -> garbage(r);
            });
        }
        return datagrams;
    }

    private static byte[] garbage(Random r) {
        return Fuzz.bytes(r, 300);
    }

    /** A valid frame damaged once: a bit flip, a truncation, an inserted byte, garbage before or after. */
    private static byte[] mutatedFrame(Random r) {
        byte[] f = validFrame(r);
        return switch (r.nextInt(5)) {
            case 0 -> flip(f, r.nextInt(f.length * 8));
            case 1 -> Arrays.copyOf(f, Fuzz.between(r, 0, f.length - 1));
            case 2 -> insert(f, Fuzz.between(r, 0, f.length), Fuzz.anyByte(r));
            case 3 -> concat(garbage(r), f);
            default -> concat(f, garbage(r));
        };
    }

    /** A frame from a handful of nodes (so nodes repeat), with a known payload and now and then a random one. */
    private static byte[] validFrame(Random r) {
        return frame(r, payload(r));
    }

    /** Correctly framed, but a bit of the payload flipped: unknown payloads, bad values, other types. */
    private static byte[] frameWithMutatedPayload(Random r) {
        byte[] p = payload(r);
        while (p.length == 0) {
            p = payload(r);
        }
        return frame(r, flip(p, r.nextInt(p.length * 8)));
    }

    private static byte[] payload(Random r) {
        return switch (Fuzz.weighted(r, 3, 5, 1)) {
            case 0 -> AmicaPayloads.encode(new KeepAlive(60, 3000, 1, Fuzz.between(r, 0, 0xFFFF), 7));
            case 1 -> switch (r.nextInt(4)) {
                case 0 -> AmicaPayloads.encode(new MotionDetection(true));
                case 1 -> AmicaPayloads.encode(new MotionDetection(false));
                case 2 -> AmicaPayloads.encode(new ReedSwitchStatus(true));
                default -> TestRadio.keepAlive(AmicaNodeType.MOVEMENT);
            };
            default -> Fuzz.bytes(r, 20);
        };
    }

    private static byte[] frame(Random r, byte[] payload) {
        return AmicaCodec.encode(new AmicaFrame(Fuzz.between(r, 1, 2), Fuzz.between(r, 1, 4),
                0, Fuzz.between(r, 0, 255), payload));
    }
}
