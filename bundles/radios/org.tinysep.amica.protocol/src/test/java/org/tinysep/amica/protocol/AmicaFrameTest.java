package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class AmicaFrameTest {

    @Test
    void copiesThePayloadOnConstructionAndAccess() {
        byte[] payload = {100, 5, 0, 1};
        AmicaFrame f = new AmicaFrame(1, 17, 0, 6, payload);
        payload[3] = 0;
        assertArrayEquals(new byte[] {100, 5, 0, 1}, f.payload());
        f.payload()[3] = 0;
        assertArrayEquals(new byte[] {100, 5, 0, 1}, f.payload());
    }

    @Test
    void equalsAndHashCodeUsePayloadContent() {
        AmicaFrame a = new AmicaFrame(1, 17, 0, 6, new byte[] {100, 5, 0, 1});
        AmicaFrame b = new AmicaFrame(1, 17, 0, 6, new byte[] {100, 5, 0, 1});
        assertEquals(a, b);
        assertEquals(a.hashCode(), b.hashCode());
        assertNotEquals(a, new AmicaFrame(1, 17, 0, 6, new byte[] {100, 5, 0, 0}));
        assertNotEquals(a, new AmicaFrame(1, 17, 0, 7, new byte[] {100, 5, 0, 1}));
        assertNotEquals(a, new AmicaFrame(2, 17, 0, 6, new byte[] {100, 5, 0, 1}));
    }

    @Test
    void toStringShowsAddressesSequenceAndHexPayload() {
        AmicaFrame f = new AmicaFrame(1, 17, 0, 6, new byte[] {100, 5, 0, 1});
        assertEquals("AmicaFrame[1.17 -> 1.0, seq=6, payload=64 05 00 01]", f.toString());
    }

    @Test
    void senderAndReceiverCombineNetgroupWithAddresses() {
        AmicaFrame up = AmicaFrame.toPlatform(new AmicaAddress(3, 9), 1, new byte[0]);
        assertEquals(new AmicaAddress(3, 9), up.sender());
        assertEquals(new AmicaAddress(3, 0), up.receiver());
        assertEquals(true, up.receiver().isPlatform());
        AmicaFrame down = AmicaFrame.fromPlatform(new AmicaAddress(3, 9), 2, new byte[0]);
        assertEquals(new AmicaFrame(3, 0, 9, 2, new byte[0]), down);
    }

    @Test
    void rejectsOutOfRangeFields() {
        byte[] p = new byte[0];
        assertThrows(IllegalArgumentException.class, () -> new AmicaFrame(256, 1, 0, 0, p));
        assertThrows(IllegalArgumentException.class, () -> new AmicaFrame(1, -1, 0, 0, p));
        assertThrows(IllegalArgumentException.class, () -> new AmicaFrame(1, 1, 256, 0, p));
        assertThrows(IllegalArgumentException.class, () -> new AmicaFrame(1, 1, 0, 256, p));
        assertThrows(IllegalArgumentException.class, () -> new AmicaFrame(1, 1, 0, 0, new byte[256]));
        assertThrows(NullPointerException.class, () -> new AmicaFrame(1, 1, 0, 0, null));
        assertEquals(255, new AmicaFrame(255, 255, 255, 255, new byte[255]).payloadLength());
    }
}
