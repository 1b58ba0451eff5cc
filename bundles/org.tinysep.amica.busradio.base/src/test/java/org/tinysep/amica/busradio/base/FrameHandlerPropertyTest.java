package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.statistics.Statistics;
import net.jqwik.api.Tuple;
import net.jqwik.api.Tuple.Tuple2;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.PacketEntry;

/**
 * The base frame logic fed random, valid and mutated frames (bit flips, truncations, insertions, garbage around
 * frames): it never throws, logs every input once, counts every rejection under the reason an independent oracle
 * (the protocol library applied by hand) expects, and creates bus devices exactly for the nodes whose valid
 * keep-alive it saw.
 */
class FrameHandlerPropertyTest {

    @Property(tries = 300)
    void everyInputIsDeliveredOrCountedUnderItsReason(@ForAll("datagrams") List<byte[]> datagrams) {
        TestRadio radio = new TestRadio();
        Set<AmicaAddress> announced = new HashSet<>();
        Map<RejectReason, Long> expected = new EnumMap<>(RejectReason.class);
        long delivered = 0;
        for (byte[] d : datagrams) {
            RejectReason reason = oracle(d, announced);
            Statistics.label("outcome").collect(reason == null ? "delivered" : reason.name());
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
        for (RejectReason r : RejectReason.values()) {
            assertEquals(expected.getOrDefault(r, 0L), radio.rejects.count(r), r.name());
        }
        long noted = packets.stream().filter(p -> !p.note().isEmpty()).count();
        assertEquals(radio.rejects.total(), noted, "each rejection noted in the packet log");
        assertTrue(packets.stream().filter(p -> !p.note().isEmpty())
                .allMatch(p -> Arrays.stream(RejectReason.values()).anyMatch(r -> p.note().startsWith(r.name()))));
        assertEquals(announced, radio.nodes.all().stream().map(AmicaBusDevice::address).collect(Collectors.toSet()));
        long devicePackets = radio.nodes.all().stream().mapToLong(d -> Long.parseLong(d.parameters().stream()
                .filter(p -> p.key().equals("packets")).findFirst().orElseThrow().value())).sum();
        assertEquals(delivered, devicePackets, "every accepted frame reached its bus device");
        // the generators must reach every outcome, or a property above would prove less than it claims
        Statistics.label("outcome").coverage(c -> {
            c.check("delivered").count(n -> n > 0);
            for (RejectReason r : RejectReason.values()) {
                c.check(r.name()).count(n -> n > 0);
            }
        });
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

    @Provide
    Arbitrary<List<byte[]>> datagrams() {
        Arbitrary<byte[]> garbage = Arbitraries.bytes().array(byte[].class).ofMaxSize(300);
        Arbitrary<byte[]> mutated = validFrames().flatMap(f -> Arbitraries.oneOf(
                Arbitraries.integers().between(0, f.length * 8 - 1).map(bit -> flip(f, bit)),
                Arbitraries.integers().between(0, f.length - 1).map(n -> Arrays.copyOf(f, n)),
                Combinators.combine(Arbitraries.integers().between(0, f.length), Arbitraries.bytes())
                        .as((at, b) -> insert(f, at, b)),
                garbage.map(g -> concat(g, f)),
                garbage.map(g -> concat(f, g))));
        return Arbitraries.frequencyOf(List.of(
                        weighted(4, validFrames()), weighted(4, mutated), weighted(2, framesWithMutatedPayloads()),
                        weighted(1, garbage)))
                .list().ofMaxSize(40);
    }

    private static Tuple2<Integer, Arbitrary<byte[]>> weighted(int weight, Arbitrary<byte[]> a) {
        return Tuple.of(weight, a);
    }

    /** Frames from a handful of nodes (so nodes repeat), with known payloads and now and then a random one. */
    static Arbitrary<byte[]> validFrames() {
        return frames(payloads());
    }

    /** Correctly framed, but a bit of the payload flipped: unknown payloads, bad values, other types. */
    static Arbitrary<byte[]> framesWithMutatedPayloads() {
        return frames(payloads().filter(p -> p.length > 0)
                .flatMap(p -> Arbitraries.integers().between(0, p.length * 8 - 1).map(bit -> flip(p, bit))));
    }

    private static Arbitrary<byte[]> payloads() {
        Arbitrary<byte[]> keepAlives = Arbitraries.integers().between(0, 0xFFFF)
                .map(product -> AmicaPayloads.encode(new KeepAlive(60, 3000, 1, product, 7)));
        Arbitrary<byte[]> known = Arbitraries.of(
                AmicaPayloads.encode(new MotionDetection(true)), AmicaPayloads.encode(new MotionDetection(false)),
                AmicaPayloads.encode(new ReedSwitchStatus(true)), TestRadio.keepAlive(AmicaNodeType.MOVEMENT));
        Arbitrary<byte[]> random = Arbitraries.bytes().array(byte[].class).ofMaxSize(20);
        return Arbitraries.frequencyOf(List.of(weighted(3, keepAlives), weighted(5, known), weighted(1, random)));
    }

    private static Arbitrary<byte[]> frames(Arbitrary<byte[]> payloads) {
        return Combinators.combine(Arbitraries.integers().between(1, 2), Arbitraries.integers().between(1, 4),
                        Arbitraries.integers().between(0, 255), payloads)
                .as((ng, src, seq, p) -> AmicaCodec.encode(new AmicaFrame(ng, src, 0, seq, p)));
    }

    static byte[] flip(byte[] f, int bit) {
        byte[] out = f.clone();
        out[bit / 8] ^= (byte) (1 << (bit % 8));
        return out;
    }

    static byte[] insert(byte[] f, int at, byte b) {
        byte[] out = new byte[f.length + 1];
        System.arraycopy(f, 0, out, 0, at);
        out[at] = b;
        System.arraycopy(f, at, out, at + 1, f.length - at);
        return out;
    }

    static byte[] concat(byte[] a, byte[] b) {
        byte[] out = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
