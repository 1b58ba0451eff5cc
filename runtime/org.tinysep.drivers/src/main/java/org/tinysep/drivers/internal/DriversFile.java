package org.tinysep.drivers.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * {@code drivers.xml} on disk. Writes are atomic ({@link AtomicFiles}) and skipped when nothing changed; a malformed
 * file is moved aside to {@code drivers.xml.broken-<timestamp>} and never read again.
 */
final class DriversFile {

    private final Path file;
    private final DriversCodec codec;
    private byte[] lastWritten;

    DriversFile(Path file, DriversCodec codec) {
        this.file = file.toAbsolutePath();
        this.codec = codec;
    }

    Path path() {
        return file;
    }

    boolean exists() {
        return Files.isRegularFile(file);
    }

    /**
     * @return the entries of the file
     * @throws MalformedDriversException when the file is not a valid list; it has then been moved aside and the
     *                                   message says where
     */
    List<DriverEntry> read(Instant now) throws IOException, MalformedDriversException {
        byte[] bytes = Files.readAllBytes(file);
        try {
            List<DriverEntry> entries = codec.read(bytes, file.getFileName().toString());
            lastWritten = bytes;
            return entries;
        } catch (MalformedDriversException e) {
            Path aside = AtomicFiles.moveAside(file, now);
            throw new MalformedDriversException(e.getMessage() + "; moved aside to " + aside.getFileName(), e);
        }
    }

    /** Writes {@code entries} atomically, unless the file already holds exactly them. @return whether it wrote */
    boolean save(List<DriverEntry> entries) throws IOException {
        byte[] bytes = codec.write(entries);
        if (lastWritten != null && Arrays.equals(bytes, lastWritten) && exists()) {
            return false;
        }
        AtomicFiles.write(file, bytes);
        lastWritten = bytes;
        return true;
    }
}
