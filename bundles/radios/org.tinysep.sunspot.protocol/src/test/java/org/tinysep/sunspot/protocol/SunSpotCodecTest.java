package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.link.frame.testing.TestBytes.concat;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class SunSpotCodecTest {

    static final SunSpotAddress SPOT_1234 = SunSpotAddress.parse("0014.4F01.0000.1234");
    static final byte[] MOVEMENT_1234 = hex("04 00 14 4F 01 00 00 12 34 02 38 04 02 01 00 01");
    static final byte[] TEMPERATURE_5678 = hex("04 00 14 4F 01 00 00 56 78 03 61 04 03 01 00 D7");
    static final byte[] LIGHT_9ABC = hex("04 00 14 4F 01 00 00 9A BC 04 2C 04 04 01 00 2A");
    static final byte[] MOVEMENT_V2_1234 =
            hex("0A 00 14 4F 01 00 00 12 34 02 A1 0A 02 02 00 01 00 FA FF 88 00 5A");

    @Test
    void checksumCoversEveryByteButItself() {
        byte[] f = MOVEMENT_1234;
        byte[] withoutCk = concat(Arrays.copyOfRange(f, 0, 10), Arrays.copyOfRange(f, 11, f.length));
        assertEquals(SunSpotCodec.crc8(withoutCk, 0, withoutCk.length), f[10] & 0xFF);
    }

    @Test
    void encodesByteExact() {
        assertArrayEquals(MOVEMENT_1234, SunSpotCodec.encode(SunSpotFrame.of(SPOT_1234, hex("02 01 00 01"))));
        assertArrayEquals(TEMPERATURE_5678, SunSpotCodec.encode(
                new SunSpotFrame(SunSpotAddress.parse("0014.4F01.0000.5678"), 3, hex("03 01 00 D7"))));
        assertArrayEquals(MOVEMENT_V2_1234, SunSpotCodec.encode(new SunSpotFrame(SPOT_1234, 2,
                SunSpotPayloads.encode(new MovementDetection(true, new Position(250, -120, 90))))));
    }

    @Test
    void decodesToTheFields() throws Exception {
        SunSpotFrame f = SunSpotCodec.decode(LIGHT_9ABC, 0, LIGHT_9ABC.length);
        assertEquals("0014.4F01.0000.9ABC", f.source().toString());
        assertEquals(4, f.sensorType());
        assertArrayEquals(hex("04 01 00 2A"), f.payload());
        assertEquals(4, f.payloadLength());
        byte[] shifted = concat(hex("FF FF"), TEMPERATURE_5678, hex("EE"));
        assertEquals(SunSpotCodec.decode(TEMPERATURE_5678, 0, TEMPERATURE_5678.length),
                SunSpotCodec.decode(shifted, 2, TEMPERATURE_5678.length));
    }

    @Test
    void highAddressBitsSurviveTheRoundTrip() throws Exception {
        SunSpotFrame f = SunSpotFrame.of(new SunSpotAddress(0xFEDC_BA98_7654_3210L), hex("05 01 00 01"));
        byte[] bytes = SunSpotCodec.encode(f);
        assertArrayEquals(hex("FE DC BA 98 76 54 32 10"), Arrays.copyOfRange(bytes, 1, 9));
        assertEquals(f, SunSpotCodec.decode(bytes, 0, bytes.length));
    }

    @Test
    void largestFrameRoundTrips() throws Exception {
        byte[] payload = new byte[SunSpotCodec.MAX_PAYLOAD];
        payload[0] = 9;
        byte[] bytes = SunSpotCodec.encode(SunSpotFrame.of(SPOT_1234, payload));
        assertEquals(SunSpotCodec.MAX_FRAME, bytes.length);
        assertEquals(267, SunSpotCodec.MAX_FRAME);
        assertArrayEquals(payload, SunSpotCodec.decode(bytes, 0, bytes.length).payload());
    }

    @Test
    void rejectsEachBrokenRuleWithItsReason() {
        byte[] badCk = MOVEMENT_1234.clone();
        badCk[10] ^= 1;
        assertReject(RejectReason.BAD_CHECKSUM, badCk, "checksum 0x39, computed 0x38");
        assertReject(RejectReason.TRUNCATED, Arrays.copyOf(MOVEMENT_1234, 15), "15 bytes, size identifier 4");
        assertReject(RejectReason.TRUNCATED, Arrays.copyOf(MOVEMENT_1234, 11), "11 bytes, a frame has at least 12");
        assertReject(RejectReason.OVERSIZE, concat(MOVEMENT_1234, hex("00")), "17 bytes, size identifier 4");
        assertReject(RejectReason.OVERSIZE, new byte[268], "268 bytes, a frame has at most 267");
        byte[] mismatch = MOVEMENT_1234.clone();
        mismatch[11] = 5;
        assertReject(RejectReason.LENGTH_MISMATCH, mismatch, "size identifier 4, payload length 5");
        byte[] wrongType = SunSpotCodec.encode(new SunSpotFrame(SPOT_1234, 3, hex("02 01 00 01")));
        assertReject(RejectReason.TYPE_MISMATCH, wrongType, "sensor type 3, payload starts with 2");
        byte[] empty = SunSpotCodec.encode(new SunSpotFrame(SPOT_1234, 2, new byte[0]));
        assertReject(RejectReason.TYPE_MISMATCH, empty, "sensor type 2, empty payload");
    }

    private static void assertReject(RejectReason reason, byte[] bytes, String detail) {
        SunSpotProtocolException e =
                assertThrows(SunSpotProtocolException.class, () -> SunSpotCodec.decode(bytes, 0, bytes.length));
        assertEquals(reason, e.reason());
        assertTrue(e.getMessage().contains(detail), e.getMessage());
        assertEquals(0, e.getStackTrace().length, "no stack trace");
    }

    @Test
    void everySingleBitFlipIsRejected() {
        for (byte[] frame : new byte[][] {MOVEMENT_1234, TEMPERATURE_5678, MOVEMENT_V2_1234}) {
            for (int bit = 0; bit < frame.length * 8; bit++) {
                byte[] b = frame.clone();
                b[bit / 8] ^= (byte) (1 << (bit % 8));
                assertThrows(SunSpotProtocolException.class, () -> SunSpotCodec.decode(b, 0, b.length),
                        "bit " + bit);
            }
        }
    }

    @Test
    void rejectsRangesOutsideTheBuffer() {
        assertThrows(IndexOutOfBoundsException.class, () -> SunSpotCodec.decode(MOVEMENT_1234, 4, 16));
        assertThrows(IndexOutOfBoundsException.class, () -> SunSpotCodec.decode(MOVEMENT_1234, -1, 4));
    }

    @Test
    void frameCopiesItsPayloadAndComparesByContent() {
        byte[] payload = hex("02 01 00 01");
        SunSpotFrame f = new SunSpotFrame(SPOT_1234, 2, payload);
        payload[3] = 0;
        assertEquals(1, f.payload()[3], "constructor copies");
        f.payload()[3] = 0;
        assertEquals(1, f.payload()[3], "accessor copies");
        SunSpotFrame same = SunSpotFrame.of(SPOT_1234, hex("02 01 00 01"));
        assertEquals(f, same);
        assertEquals(f.hashCode(), same.hashCode());
        assertNotEquals(f, new SunSpotFrame(SPOT_1234, 3, hex("02 01 00 01")));
        assertNotEquals(f, SunSpotFrame.of(new SunSpotAddress(1), hex("02 01 00 01")));
        assertEquals("SunSpotFrame[0014.4F01.0000.1234, type=2, payload=02 01 00 01]", f.toString());
    }

    @Test
    void frameChecksItsFields() {
        assertThrows(IllegalArgumentException.class, () -> new SunSpotFrame(SPOT_1234, 256, new byte[1]));
        assertThrows(IllegalArgumentException.class, () -> new SunSpotFrame(SPOT_1234, -1, new byte[1]));
        assertThrows(IllegalArgumentException.class, () -> new SunSpotFrame(SPOT_1234, 2, new byte[256]));
        assertThrows(NullPointerException.class, () -> new SunSpotFrame(null, 2, new byte[1]));
        assertThrows(NullPointerException.class, () -> new SunSpotFrame(SPOT_1234, 2, null));
        assertThrows(IllegalArgumentException.class, () -> SunSpotFrame.of(SPOT_1234, new byte[0]));
        assertEquals(200, SunSpotFrame.of(SPOT_1234, new byte[] {(byte) 200}).sensorType(), "unsigned");
    }
}
