package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class AmicaAddressTest {

    @Test
    void writesNetgroupDotAddress() {
        assertEquals("1.17", new AmicaAddress(1, 17).toString());
        assertEquals("255.0", new AmicaAddress(255, 0).toString());
    }

    @Test
    void parsesWhatItWrites() {
        for (int ng = 0; ng < 256; ng += 51) {
            for (int a = 0; a < 256; a += 17) {
                AmicaAddress address = new AmicaAddress(ng, a);
                assertEquals(address, AmicaAddress.parse(address.toString()));
            }
        }
        assertEquals(new AmicaAddress(1, 17), AmicaAddress.parse("1.17"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "1", "1.", ".1", "1.17.3", "256.1", "1.256", "-1.2", "1.+2", "a.b", " 1.17", "1.1000"})
    void rejectsMalformedText(String text) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> AmicaAddress.parse(text));
        assertTrue(e.getMessage().contains("AmICA address"), e.getMessage());
    }

    @Test
    void rejectsNullText() {
        assertThrows(IllegalArgumentException.class, () -> AmicaAddress.parse(null));
    }

    @Test
    void rejectsOutOfRangeFields() {
        assertThrows(IllegalArgumentException.class, () -> new AmicaAddress(-1, 0));
        assertThrows(IllegalArgumentException.class, () -> new AmicaAddress(0, 256));
    }

    @Test
    void addressZeroIsThePlatform() {
        assertTrue(new AmicaAddress(4, 0).isPlatform());
        assertFalse(new AmicaAddress(4, 1).isPlatform());
    }

    @Test
    void equalAddressesAreEqualAndEveryAddressHashesApart() {
        java.util.Set<Integer> hashes = new java.util.HashSet<>();
        for (int ng = 0; ng < 256; ng++) {
            for (int a = 0; a < 256; a++) {
                AmicaAddress x = new AmicaAddress(ng, a);
                assertEquals(x, new AmicaAddress(ng, a));
                assertEquals(x.hashCode(), new AmicaAddress(ng, a).hashCode());
                assertEquals(x, AmicaAddress.of(ng, a));
                hashes.add(x.hashCode());
            }
        }
        assertEquals(65_536, hashes.size());
        assertFalse(new AmicaAddress(1, 2).equals(new AmicaAddress(2, 1)));
        assertFalse(new AmicaAddress(1, 2).equals("1.2"));
        assertThrows(IllegalArgumentException.class, () -> AmicaAddress.of(256, 0));
        assertThrows(IllegalArgumentException.class, () -> AmicaAddress.of(0, -1));
    }

    /** Issue 29, item 1: the receive thread asks each frame for its sender; that is no new object per frame. */
    @Test
    void aFramesSenderIsNoNewObjectPerFrame() {
        AmicaFrame frame = new AmicaFrame(3, 200, 0, 1, new byte[] {1});
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean)
                java.lang.management.ManagementFactory.getThreadMXBean();
        long sum = 0;
        for (int i = 0; i < 20_000; i++) {
            sum += frame.sender().address();
        }
        long before = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
        for (int i = 0; i < 20_000; i++) {
            sum += frame.sender().address();
        }
        double bytes = (mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - before) / 20_000.0;
        assertTrue(bytes < 16, "bytes allocated per frame for its sender's address: " + bytes);
        assertEquals(2 * 20_000L * 200, sum);
        assertEquals(new AmicaAddress(3, 200), frame.sender());
    }
}
