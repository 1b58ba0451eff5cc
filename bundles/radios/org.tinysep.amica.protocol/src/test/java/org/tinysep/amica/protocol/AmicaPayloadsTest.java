package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.tinysep.link.frame.testing.TestBytes.dec;

import java.util.EnumSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class AmicaPayloadsTest {

    @Test
    void keepAliveIsBigEndianWithBatteryInMillivoltsAndFullSerialNumber() throws Exception {
        byte[] bytes = dec("82 0 0 0 14 16 11 184 0 1 0 3 18 52 86 120");
        KeepAlive k = (KeepAlive) AmicaPayloads.decode(bytes);
        assertEquals(3600, k.uptimeSeconds());
        assertEquals(3000, k.batteryMillivolts());
        assertEquals(1, k.vendorId());
        assertEquals(3, k.productId());
        assertEquals(0x12345678L, k.serialNumber(), "serial number includes its last byte O");
        assertEquals(EnumSet.of(AmicaNodeType.MOVEMENT, AmicaNodeType.DOOR), k.nodeTypes());
        assertArrayEquals(bytes, AmicaPayloads.encode(k));
    }

    @Test
    void keepAliveKeepsUnsignedMaximums() throws Exception {
        KeepAlive max = new KeepAlive(0xFFFF_FFFFL, 65535, 65535, 65535, 0xFFFF_FFFFL);
        byte[] bytes = AmicaPayloads.encode(max);
        assertArrayEquals(dec("82 0 255 255 255 255 255 255 255 255 255 255 255 255 255 255"), bytes);
        assertEquals(max, AmicaPayloads.decode(bytes));
    }

    @Test
    void statusPayloadsEncodeByteExact() {
        assertArrayEquals(dec("100 3 0 1"), AmicaPayloads.encode(new ReedSwitchStatus(true)));
        assertArrayEquals(dec("100 3 0 0"), AmicaPayloads.encode(new ReedSwitchStatus(false)));
        assertArrayEquals(dec("100 5 0 1"), AmicaPayloads.encode(new MotionDetection(true)));
        assertArrayEquals(dec("100 5 0 0"), AmicaPayloads.encode(new MotionDetection(false)));
        assertArrayEquals(dec("5 2 0 40"), AmicaPayloads.encode(new LightControl(40)));
        assertArrayEquals(dec("5 4 0 100"), AmicaPayloads.encode(new SpeakerControl(100)));
        assertArrayEquals(dec("5 8 0 0"), AmicaPayloads.encode(new HeaterControl(0)));
    }

    @Test
    void everyPayloadRoundTrips() throws Exception {
        List<AmicaPayload> all = List.of(new KeepAlive(1, 2, 3, 4, 5), new KeepAlive(0, 0, 0, 0, 0),
                new ReedSwitchStatus(true), new ReedSwitchStatus(false), new MotionDetection(true),
                new MotionDetection(false), new LightControl(0), new LightControl(100), new SpeakerControl(55),
                new HeaterControl(99));
        for (AmicaPayload p : all) {
            assertEquals(p, AmicaPayloads.decode(AmicaPayloads.encode(p)), p.toString());
        }
    }

    @Test
    void everyPercentRoundTrips() throws Exception {
        for (int percent = 0; percent <= 100; percent++) {
            assertEquals(new LightControl(percent), AmicaPayloads.decode(dec("5 2 0 " + percent)));
            assertEquals(new SpeakerControl(percent), AmicaPayloads.decode(dec("5 4 0 " + percent)));
            assertEquals(new HeaterControl(percent), AmicaPayloads.decode(dec("5 8 0 " + percent)));
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "82", "7 7 0 1", "100 4 0 1", "5 1 0 1", "0 0", "82 1 0 0 0 0 0 0 0 0 0 0 0 0 0 0"})
    void rejectsUnknownPayloads(String decimal) {
        assertPayloadReject(RejectReason.UNKNOWN_PAYLOAD, dec(decimal));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "100 3 0 2", "100 5 0 255", "5 2 0 101", "5 4 0 200", "5 8 0 101", // value out of range
        "100 3 1 1", "100 5 7 0", "5 2 1 40", "5 4 255 0", "5 8 1 0", // third byte not 0
        "100 3 0", "100 5 0 1 0", "5 2", "5 8 0 40 40", // wrong length
        "82 0 0 0 14 16 11 184 0 1 0 3 18 52 86", "82 0 0 0 14 16 11 184 0 1 0 3 18 52 86 120 0"})
    void rejectsBadValues(String decimal) {
        assertPayloadReject(RejectReason.BAD_VALUE, dec(decimal));
    }

    @Test
    void recordsRejectValuesTheirBytesCannotHold() {
        assertThrows(IllegalArgumentException.class, () -> new LightControl(101));
        assertThrows(IllegalArgumentException.class, () -> new SpeakerControl(-1));
        assertThrows(IllegalArgumentException.class, () -> new HeaterControl(255));
        assertThrows(IllegalArgumentException.class, () -> new KeepAlive(-1, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new KeepAlive(0x1_0000_0000L, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new KeepAlive(0, 65536, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new KeepAlive(0, 0, -1, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new KeepAlive(0, 0, 0, 65536, 0));
        assertThrows(IllegalArgumentException.class, () -> new KeepAlive(0, 0, 0, 0, 0x1_0000_0000L));
    }

    static void assertPayloadReject(RejectReason expected, byte[] payload) {
        AmicaProtocolException e =
                assertThrows(AmicaProtocolException.class, () -> AmicaPayloads.decode(payload));
        assertEquals(expected, e.reason(), e.getMessage());
    }
}
