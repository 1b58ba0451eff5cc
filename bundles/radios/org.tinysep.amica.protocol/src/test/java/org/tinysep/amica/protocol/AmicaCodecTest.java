package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.link.frame.testing.TestBytes.concat;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

class AmicaCodecTest {

    static final byte[] KEEP_ALIVE_1_17 =
            hex("10 A1 11 00 01 05 DB 10 52 00 00 00 0E 10 0B B8 00 01 00 03 12 34 56 78");
    static final byte[] MOVEMENT_1_17 = hex("04 A1 11 00 01 06 2B 04 64 05 00 01");
    static final byte[] REED_OPEN_1_18 = hex("04 A1 12 00 01 2A 0D 04 64 03 00 01");
    static final byte[] LIGHT_40_TO_1_20 = hex("04 A1 00 14 01 00 D0 04 05 02 00 28");

    @Test
    void encodesKeepAliveFrom1_17ByteExact() {
        byte[] payload = hex("52 00 00 00 0E 10 0B B8 00 01 00 03 12 34 56 78");
        AmicaFrame frame = AmicaFrame.toPlatform(AmicaAddress.parse("1.17"), 5, payload);
        assertArrayEquals(KEEP_ALIVE_1_17, AmicaCodec.encode(frame));
    }

    @Test
    void encodesStatusFramesAndCommandByteExact() {
        assertArrayEquals(MOVEMENT_1_17, AmicaCodec.encode(new AmicaFrame(1, 17, 0, 6, hex("64 05 00 01"))));
        assertArrayEquals(REED_OPEN_1_18, AmicaCodec.encode(new AmicaFrame(1, 18, 0, 42, hex("64 03 00 01"))));
        AmicaFrame command = AmicaFrame.fromPlatform(new AmicaAddress(1, 20), 0, new byte[] {5, 2, 0, 40});
        assertArrayEquals(LIGHT_40_TO_1_20, AmicaCodec.encode(command));
    }

    @Test
    void decodesVectorsToTheirFields() throws Exception {
        AmicaFrame f = AmicaCodec.decode(LIGHT_40_TO_1_20, 0, LIGHT_40_TO_1_20.length);
        assertEquals(new AmicaAddress(1, 0), f.sender());
        assertEquals(new AmicaAddress(1, 20), f.receiver());
        assertEquals(0, f.sequence());
        assertArrayEquals(new byte[] {5, 2, 0, 40}, f.payload());

        AmicaFrame k = AmicaCodec.decode(KEEP_ALIVE_1_17, 0, KEEP_ALIVE_1_17.length);
        assertEquals("1.17", k.sender().toString());
        assertEquals(5, k.sequence());
        assertEquals(16, k.payloadLength());
    }

    @Test
    void decodesAFrameInsideALargerBuffer() throws Exception {
        byte[] buf = concat(hex("FF FF FF"), MOVEMENT_1_17, hex("EE"));
        AmicaFrame f = AmicaCodec.decode(buf, 3, MOVEMENT_1_17.length);
        assertEquals(new AmicaFrame(1, 17, 0, 6, hex("64 05 00 01")), f);
    }

    @Test
    void roundTripsEmptyAndMaximumPayloads() throws Exception {
        byte[] max = new byte[AmicaCodec.MAX_PAYLOAD];
        new Random(3).nextBytes(max);
        for (byte[] payload : new byte[][] {new byte[0], max}) {
            AmicaFrame f = new AmicaFrame(200, 201, 202, 203, payload);
            byte[] bytes = AmicaCodec.encode(f);
            assertEquals(AmicaCodec.HEADER_LENGTH + payload.length, bytes.length);
            assertEquals(f, AmicaCodec.decode(bytes, 0, bytes.length));
        }
        assertEquals(263, AmicaCodec.MAX_FRAME);
    }

    @Test
    void rejectsFewerThanEightBytesAsTruncated() {
        assertReject(RejectReason.TRUNCATED, hex("04 A1 11 00 01"));
        assertReject(RejectReason.TRUNCATED, new byte[0]);
    }

    @Test
    void rejectsFewerBytesThanAnnouncedAsTruncated() {
        assertReject(RejectReason.TRUNCATED, Arrays.copyOf(MOVEMENT_1_17, MOVEMENT_1_17.length - 1));
    }

    @Test
    void rejectsMoreBytesThanAnnouncedAsOversize() {
        assertReject(RejectReason.OVERSIZE, concat(MOVEMENT_1_17, hex("00")));
    }

    @Test
    void rejectsMoreThan263BytesAsOversize() {
        byte[] max = AmicaCodec.encode(new AmicaFrame(1, 1, 0, 0, new byte[255]));
        assertReject(RejectReason.OVERSIZE, concat(max, hex("00")));
    }

    @Test
    void rejectsWrongHeaderValue() {
        byte[] b = LIGHT_40_TO_1_20.clone();
        b[1] = (byte) 0xA2;
        AmicaProtocolException e = assertReject(RejectReason.BAD_HEADER, b);
        assertTrue(e.getMessage().contains("0xA2"), e.getMessage());
    }

    @Test
    void rejectsSizeIdentifierDifferentFromPayloadLength() {
        byte[] b = MOVEMENT_1_17.clone();
        b[7] = 5;
        assertReject(RejectReason.LENGTH_MISMATCH, b);
    }

    @Test
    void rejectsEverySingleBitError() {
        for (int bit = 0; bit < KEEP_ALIVE_1_17.length * 8; bit++) {
            int index = bit / 8;
            byte[] b = KEEP_ALIVE_1_17.clone();
            b[index] ^= (byte) (1 << (bit % 8));
            RejectReason expected = index == 0 || index == 7 ? RejectReason.LENGTH_MISMATCH
                    : index == 1 ? RejectReason.BAD_HEADER : RejectReason.BAD_CHECKSUM;
            AmicaProtocolException e = assertThrows(AmicaProtocolException.class,
                    () -> AmicaCodec.decode(b, 0, b.length), "bit " + bit);
            assertEquals(expected, e.reason(), "bit " + bit);
        }
    }

    @Test
    void badChecksumMessageNamesBothValues() {
        byte[] b = LIGHT_40_TO_1_20.clone();
        b[6] = (byte) 0xD1;
        AmicaProtocolException e = assertReject(RejectReason.BAD_CHECKSUM, b);
        assertTrue(e.getMessage().contains("0xD1") && e.getMessage().contains("0xD0"), e.getMessage());
        assertTrue(e.getMessage().startsWith("BAD_CHECKSUM"), e.getMessage());
        assertEquals(0, e.getStackTrace().length, "no stack trace for expected rejections");
    }

    @Test
    void rejectsRangesOutsideTheBuffer() {
        assertThrows(IndexOutOfBoundsException.class, () -> AmicaCodec.decode(MOVEMENT_1_17, 1, 12));
        assertThrows(IndexOutOfBoundsException.class, () -> AmicaCodec.crc8(MOVEMENT_1_17, -1, 2));
    }

    static AmicaProtocolException assertReject(RejectReason expected, byte[] bytes) {
        AmicaProtocolException e =
                assertThrows(AmicaProtocolException.class, () -> AmicaCodec.decode(bytes, 0, bytes.length));
        assertEquals(expected, e.reason(), e.getMessage());
        return e;
    }
}
