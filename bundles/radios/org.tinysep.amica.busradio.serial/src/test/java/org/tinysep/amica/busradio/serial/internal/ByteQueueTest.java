package org.tinysep.amica.busradio.serial.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class ByteQueueTest {

    @Test
    void bytesComeOutInOrderAcrossTheWrapAround() {
        ByteQueue q = new ByteQueue(5);
        q.append(new byte[] {1, 2, 3, 4}, 0, 4);
        assertArrayEquals(new byte[] {1, 2, 3}, q.take(3));
        q.append(new byte[] {9, 5, 6, 7}, 1, 3);
        assertEquals(4, q.size());
        assertArrayEquals(new byte[] {4, 5, 6, 7}, q.take(10));
        assertEquals(0, q.size());
    }

    @Test
    void whenFullTheOldestBytesGiveWay() {
        ByteQueue q = new ByteQueue(4);
        q.append(new byte[] {1, 2, 3}, 0, 3);
        q.append(new byte[] {4, 5, 6}, 0, 3);
        assertArrayEquals(new byte[] {3, 4, 5, 6}, q.take(4));
        q.append(new byte[] {1, 2, 3, 4, 5, 6, 7}, 0, 7);
        assertArrayEquals(new byte[] {4, 5, 6, 7}, q.take(4));
        q.append(new byte[] {1}, 0, 1);
        q.clear();
        assertEquals(0, q.size());
    }
}
