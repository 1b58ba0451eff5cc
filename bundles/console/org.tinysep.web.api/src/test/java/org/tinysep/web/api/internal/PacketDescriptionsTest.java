package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.packet.PacketDescriber;
import org.tinysep.web.api.internal.PacketDescriptions.Description;

/**
 * The packet log in words through the registered describers (whiteboard): the one usual for the origin first, one
 * per protocol, and a packet no protocol recognises shown undecoded with the reason.
 */
class PacketDescriptionsTest {

    /** Recognises packets whose first byte is {@code marker}; usual for origins containing {@code usual}. */
    private static final class Fake implements PacketDescriber {
        final String protocol;
        final byte marker;
        final String usual;
        final AtomicInteger asked = new AtomicInteger();

        Fake(String protocol, int marker, String usual) {
            this.protocol = protocol;
            this.marker = (byte) marker;
            this.usual = usual;
        }

        @Override
        public String protocol() {
            return protocol;
        }

        @Override
        public boolean usualFor(String origin) {
            return origin.contains(usual);
        }

        @Override
        public Optional<String> describe(byte[] bytes) {
            asked.incrementAndGet();
            return bytes[0] == marker || marker == 0 ? Optional.of(protocol + " frame") : Optional.empty();
        }
    }

    private final PacketDescriptions descriptions = new PacketDescriptions();

    @Test
    void withoutAnyDescriberAPacketIsShownUndecodedSayingWhy() {
        assertEquals(new Description("", "not decoded: no bus radio that describes its packets is running"),
                descriptions.describe("node 1.17 via udp", new byte[] {1, 2}));
    }

    @Test
    void theDescriberThatRecognisesThePacketTellsIt() {
        descriptions.add(new Fake("AmICA", 1, "AmICA"));
        descriptions.add(new Fake("Sun SPOT", 2, "SunSpot"));
        assertEquals(new Description("AmICA frame", ""), descriptions.describe("node 1.17", new byte[] {1}));
        assertEquals(new Description("Sun SPOT frame", ""), descriptions.describe("node 1.17", new byte[] {2}));
    }

    @Test
    void theDescriberUsualForTheOriginIsAskedFirst() {
        Fake amica = new Fake("AmICA", 0, "via serial");
        Fake sunSpot = new Fake("Sun SPOT", 0, "SunSpot");
        descriptions.add(amica);
        descriptions.add(sunSpot);
        assertEquals("Sun SPOT frame", descriptions.describe("SunSpotBusRadio", new byte[] {5}).decoded());
        assertEquals("AmICA frame", descriptions.describe("node 1.17 via serial", new byte[] {5}).decoded());
    }

    @Test
    void anUnknownPacketIsShownUndecodedNamingTheProtocolsAskedOnceEach() {
        Fake udp = new Fake("AmICA", 1, "x");
        Fake serial = new Fake("AmICA", 1, "x");
        descriptions.add(udp);
        descriptions.add(serial);
        descriptions.add(new Fake("Sun SPOT", 2, "x"));
        assertEquals(new Description("", "not decoded: the bytes are no AmICA or Sun SPOT frame (the protocols running "
                + "here)"), descriptions.describe("somewhere", new byte[] {9}));
        assertEquals(1, udp.asked.get() + serial.asked.get(), "one AmICA describer is enough");
    }

    @Test
    void aFailingDescriberIsNamedAndTheOthersStillAsked() {
        descriptions.add(new PacketDescriber() {
            @Override
            public String protocol() {
                return "Broken";
            }

            @Override
            public Optional<String> describe(byte[] bytes) {
                throw new IllegalStateException("decoder bug");
            }
        });
        Fake amica = new Fake("AmICA", 1, "x");
        descriptions.add(amica);
        assertEquals("AmICA frame", descriptions.describe("o", new byte[] {1}).decoded());
        String why = descriptions.describe("o", new byte[] {7}).undecoded();
        assertEquals("not decoded: the bytes are no AmICA frame (the protocols running here); the Broken description "
                + "failed (java.lang.IllegalStateException: decoder bug)", why);
    }

    @Test
    void aDescriberThatWentAwayIsNotAskedAnyMore() {
        Fake amica = new Fake("AmICA", 1, "x");
        descriptions.add(amica);
        descriptions.remove(amica);
        assertTrue(descriptions.describe("o", new byte[] {1}).undecoded().contains("no bus radio"));
        assertEquals(0, amica.asked.get());
    }

    @Test
    void aPacketWithoutBytesSaysSo() {
        descriptions.add(new Fake("AmICA", 0, "x"));
        assertEquals(new Description("", "not decoded: no bytes of this packet were kept"),
                descriptions.describe("o", new byte[0]));
    }

    @Test
    void thePacketLogsJsonCarriesTheWordsOrTheReason() {
        descriptions.add(new Fake("AmICA", 1, "x"));
        Map<String, Object> told = LogsApi.packet(new PacketEntry(1, Instant.EPOCH, Direction.RECEIVED, "node 1.17",
                new byte[] {1, 2}, ""), descriptions);
        assertEquals("AmICA frame", told.get("decoded"));
        assertEquals("", told.get("undecoded"));
        Map<String, Object> not = LogsApi.packet(new PacketEntry(2, Instant.EPOCH, Direction.RECEIVED, "node 1.17",
                new byte[] {3}, ""), descriptions);
        assertEquals("", not.get("decoded"));
        assertEquals("not decoded: the bytes are no AmICA frame (the protocols running here)", not.get("undecoded"));
    }
}
