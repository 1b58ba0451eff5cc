package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.link.frame.testing.TestBytes.dec;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import org.junit.jupiter.api.Test;

class SunSpotPayloadsTest {

    private static SunSpotPayload decode(String decimal) throws SunSpotProtocolException {
        return SunSpotPayloads.decode(dec(decimal));
    }

    /** @param payloads decimal payloads, each rejected with {@code reason} */
    private static void assertReject(RejectReason reason, String... payloads) {
        for (String decimal : payloads) {
            SunSpotProtocolException e = assertThrows(SunSpotProtocolException.class, () -> decode(decimal), decimal);
            assertEquals(reason, e.reason(), decimal);
        }
    }

    @Test
    void decodesEveryPayloadOfTable32() throws Exception {
        assertEquals(new MovementDetection(true), decode("2 1 0 1"));
        assertEquals(new MovementDetection(false), decode("2 1 0 0"));
        assertEquals(new TemperatureStatus(21.5), decode("3 1 0 215"));
        assertEquals(new LightStatus(100), decode("4 1 0 100"));
        assertEquals(new LightStatus(0), decode("4 1 0 0"));
        assertEquals(new PetMovementDetection(true), decode("5 1 0 1"));
        assertNull(((MovementDetection) decode("2 1 0 1")).position());
    }

    @Test
    void decodesMovementVersion2WithSignedCoordinates() throws Exception {
        MovementDetection m = (MovementDetection) SunSpotPayloads.decode(hex("02 02 00 01 80 00 7F FF FF FF"));
        assertTrue(m.detected());
        assertEquals(new Position(-32768, 32767, -1), m.position());
        assertEquals(2, m.version());
        assertEquals(1, new MovementDetection(false).version());
        assertEquals(new MovementDetection(false, new Position(0, 0, 0)), decode("2 2 0 0 0 0 0 0 0 0"));
    }

    @Test
    void temperatureIsSignedTenthsOfADegree() throws Exception {
        assertEquals(-12.3, ((TemperatureStatus) SunSpotPayloads.decode(hex("03 01 FF 85"))).celsius());
        assertEquals(125.0, ((TemperatureStatus) SunSpotPayloads.decode(hex("03 01 04 E2"))).celsius());
        assertEquals(-40.0, ((TemperatureStatus) SunSpotPayloads.decode(hex("03 01 FE 70"))).celsius());
        assertEquals(0.0, ((TemperatureStatus) decode("3 1 0 0")).celsius());
        assertEquals(25.6, ((TemperatureStatus) decode("3 1 1 0")).celsius(), "A is the high byte");
        assertReject(RejectReason.BAD_VALUE, "3 1 4 227");
        assertReject(RejectReason.BAD_VALUE, "3 1 254 111");
        assertReject(RejectReason.BAD_VALUE, "3 1 128 0");
    }

    @Test
    void encoderRoundsTemperatureToTenths() {
        assertArrayEquals(hex("03 01 00 D7"), SunSpotPayloads.encode(new TemperatureStatus(21.54)));
        assertArrayEquals(hex("03 01 00 D8"), SunSpotPayloads.encode(new TemperatureStatus(21.55)));
        assertArrayEquals(hex("03 01 FF 85"), SunSpotPayloads.encode(new TemperatureStatus(-12.3)));
        assertArrayEquals(hex("03 01 04 E2"), SunSpotPayloads.encode(new TemperatureStatus(125.0)));
        for (int tenths = -400; tenths <= 1250; tenths++) {
            TemperatureStatus t = TemperatureStatus.ofTenths(tenths);
            assertEquals(tenths, t.tenths());
        }
    }

    @Test
    void everyPayloadRoundTrips() throws Exception {
        SunSpotPayload[] all = {new MovementDetection(true), new MovementDetection(false, new Position(1, -2, 3)),
            new TemperatureStatus(-39.9), new TemperatureStatus(99.9), new LightStatus(57),
            new PetMovementDetection(false), new PetMovementDetection(true)};
        for (SunSpotPayload p : all) {
            assertEquals(p, SunSpotPayloads.decode(SunSpotPayloads.encode(p)), p.toString());
        }
        assertEquals(10, SunSpotPayloads.encode(all[1]).length);
        assertArrayEquals(dec("2 2 0 0 0 1 255 254 0 3"), SunSpotPayloads.encode(all[1]));
    }

    @Test
    void rejectsWrongLengthsReservedBytesAndRanges() {
        assertReject(RejectReason.BAD_VALUE, "2 1 0 2", "2 1 1 1", "2 1 0", "2 1 0 1 0", "2 2 0 1 0 0 0 0 0",
                "2 2 0 1 0 0 0 0 0 0 0", "2 2 7 1 0 0 0 0 0 0", "2 2 0 3 0 0 0 0 0 0", "3 1 0", "4 1 0 101",
                "4 1 0 255", "4 1 1 50", "5 1 0 2", "5 1 9 0");
    }

    @Test
    void rejectsUnknownPayloads() {
        assertReject(RejectReason.UNKNOWN_PAYLOAD, "", "2", "2 3 0 1", "3 2 0 1", "1 1 0 1", "6 1 0 1", "100 5 0 1");
        assertThrows(NullPointerException.class, () -> SunSpotPayloads.decode(null));
    }

    @Test
    void recordsCheckTheirRanges() {
        assertThrows(IllegalArgumentException.class, () -> new LightStatus(101));
        assertThrows(IllegalArgumentException.class, () -> new LightStatus(-1));
        assertThrows(IllegalArgumentException.class, () -> new TemperatureStatus(125.01));
        assertThrows(IllegalArgumentException.class, () -> new TemperatureStatus(-40.01));
        assertThrows(IllegalArgumentException.class, () -> new TemperatureStatus(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new Position(32768, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new Position(0, -32769, 0));
        assertThrows(IllegalArgumentException.class, () -> new Position(0, 0, 40000));
        assertThrows(NullPointerException.class, () -> SunSpotPayloads.encode(null));
    }

    @Test
    void payloadsKnowTheirSensorType() {
        assertEquals(SunSpotSensorType.MOVEMENT, new MovementDetection(true, new Position(1, 1, 1)).sensorType());
        assertEquals(SunSpotSensorType.TEMPERATURE, new TemperatureStatus(1).sensorType());
        assertEquals(SunSpotSensorType.LIGHT, new LightStatus(1).sensorType());
        assertEquals(SunSpotSensorType.PET_COLLAR, new PetMovementDetection(true).sensorType());
    }
}
