package org.tinysep.testsupport.serial;

import java.io.ByteArrayOutputStream;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Test utility: the far end of a pseudo-terminal pair ({@link SocatPair#b()}), opened as plain files, playing the
 * device behind the port: writes bytes, reads them with a deadline.
 */
public final class PtyPeer implements AutoCloseable {

    private final FileInputStream in;
    private final FileOutputStream out;

    /** @param path the pseudo-terminal (or its link path) to open for writing and reading */
    public PtyPeer(Path path) throws IOException {
        this.out = new FileOutputStream(path.toFile());
        this.in = new FileInputStream(path.toFile());
    }

    /** Writes and flushes {@code bytes}. */
    public void write(byte[] bytes) throws IOException {
        out.write(bytes);
        out.flush();
    }

    /**
     * @return exactly {@code n} bytes
     * @throws AssertionError when they have not all arrived within 5 s
     */
    public byte[] read(int n) throws IOException, InterruptedException {
        ByteArrayOutputStream got = new ByteArrayOutputStream();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (got.size() < n) {
            int available = in.available();
            if (available > 0) {
                byte[] b = new byte[Math.min(available, n - got.size())];
                got.write(b, 0, in.read(b));
            } else if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out reading " + n + " bytes at the peer end, got " + got.size());
            } else {
                Thread.sleep(5);
            }
        }
        return got.toByteArray();
    }

    @Override
    public void close() throws IOException {
        try {
            in.close();
        } finally {
            out.close();
        }
    }
}
