package org.tinysep.amica.busradio.serial.internal;

import java.util.Arrays;

/**
 * The raw bytes fed to a stream decoder and not yet accounted for by a frame or a skipped run, in order, so the
 * packet log can show the exact bytes of each. Bounded: when full, the oldest bytes give way (a {@link #take}
 * then returns fewer bytes than asked), so a bug elsewhere can never make it grow without limit.
 */
final class ByteQueue {

    private final byte[] buf;
    private int head;
    private int size;

    ByteQueue(int capacity) {
        this.buf = new byte[capacity];
    }

    void append(byte[] src, int off, int len) {
        if (len >= buf.length) {
            off += len - buf.length;
            len = buf.length;
        }
        int overflow = size + len - buf.length;
        if (overflow > 0) {
            discard(overflow);
        }
        for (int i = 0; i < len; i++) {
            buf[(head + size + i) % buf.length] = src[off + i];
        }
        size += len;
    }

    /** @return the oldest {@code n} bytes (fewer if fewer are queued), removed from the queue */
    byte[] take(int n) {
        int k = Math.min(n, size);
        byte[] out = new byte[k];
        for (int i = 0; i < k; i++) {
            out[i] = buf[(head + i) % buf.length];
        }
        discard(k);
        return out;
    }

    void clear() {
        head = 0;
        size = 0;
        Arrays.fill(buf, (byte) 0);
    }

    int size() {
        return size;
    }

    private void discard(int n) {
        head = (head + n) % buf.length;
        size -= n;
    }
}
