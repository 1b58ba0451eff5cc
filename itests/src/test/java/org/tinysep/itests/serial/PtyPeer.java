package org.tinysep.itests.serial;

import java.io.ByteArrayOutputStream;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * The far end of a pseudo-terminal pair, opened as plain files: writes bytes, reads them with a deadline. A
 * deliberate copy of {@code org.tinysep.serial.support.testing.PtyPeer}: the probe bundle cannot load that package
 * (see {@link SocatPair}).
 */
final class PtyPeer implements AutoCloseable {

    private final FileInputStream in;
    private final FileOutputStream out;

    PtyPeer(Path path) throws IOException {
        this.out = new FileOutputStream(path.toFile());
        this.in = new FileInputStream(path.toFile());
    }

    void write(byte[] bytes) throws IOException {
        out.write(bytes);
        out.flush();
    }

    /** @return exactly {@code n} bytes, or fails after 5 s */
    byte[] read(int n) throws IOException, InterruptedException {
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
