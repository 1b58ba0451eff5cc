package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import javax.crypto.Mac;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * Streams an archive into a staging folder, entry by entry, counting the bytes as they are inflated (the sizes
 * in the zip's headers are never trusted): an archive that expands past {@link Limits#maxTotalBytes} or has one
 * entry past {@link Limits#maxEntryBytes} is refused at that byte, so a zip bomb costs one buffer of memory. Names
 * outside the archive's layout and repeated names are collected as problems. Nothing outside the staging folder
 * is written.
 */
final class ArchiveUnpacker {

    static final Pattern NAME = Pattern.compile("backup/[A-Za-z0-9_-][A-Za-z0-9._-]*/[A-Za-z0-9_-][A-Za-z0-9._-]*\\.xml"
            + "|house\\.xml|drivers\\.xml|etc/[A-Za-z0-9_-][A-Za-z0-9._-]*\\.cfg|secrets/[A-Za-z0-9_-][A-Za-z0-9._-]*|"
            + Pattern.quote(ArchiveSignature.ENTRY));
    private static final int BUFFER = 64 * 1024;

    /** Bounds on what a restore reads. */
    record Limits(long maxTotalBytes, long maxEntryBytes, int maxEntries) {
    }

    /** What was staged: the folder, the entry names in archive order, the signature entry (or null), problems. */
    record Unpacked(Path folder, List<String> names, byte[] signature, List<String> problems) {
    }

    /** Thrown when the archive exceeds a limit: reading stops there. */
    static final class TooLarge extends IOException {
        private static final long serialVersionUID = 1L;

        TooLarge(String message) {
            super(message);
        }
    }

    private ArchiveUnpacker() {
    }

    /**
     * @param mac fed with every entry but the signature ({@link ArchiveSignature}); null: not computed
     * @throws TooLarge   when a limit is passed
     * @throws IOException when the file is not a readable zip
     */
    static Unpacked unpack(Path archive, Path staging, Limits limits, Mac mac) throws IOException {
        AtomicFiles.createPrivateDirectories(staging);
        List<String> names = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        byte[] signature = null;
        long total = 0;
        int entries = 0;
        byte[] buffer = new byte[BUFFER];
        try (ZipInputStream zip = new ZipInputStream(Files.newInputStream(archive))) {
            for (ZipEntry e; (e = zip.getNextEntry()) != null; ) {
                if (++entries > limits.maxEntries()) {
                    throw new TooLarge("more than " + limits.maxEntries() + " entries");
                }
                String name = e.getName();
                boolean wanted = !e.isDirectory() && NAME.matcher(name).matches();
                if (!e.isDirectory() && !wanted) {
                    problems.add(name + ": not a file a TinySEP archive holds");
                }
                if (wanted && !seen.add(name)) {
                    problems.add(name + ": appears more than once in the archive (which one is meant?)");
                    wanted = false;
                }
                boolean isSignature = name.equals(ArchiveSignature.ENTRY);
                if (wanted && mac != null && !isSignature) {
                    ArchiveSignature.begin(mac, name);
                }
                long size = 0;
                try (OutputStream out = wanted ? Files.newOutputStream(AtomicFiles.createPrivateFile(
                        staging.resolve(name))) : OutputStream.nullOutputStream()) {
                    for (int n; (n = zip.read(buffer)) > 0; ) {
                        size += n;
                        total += n;
                        if (size > limits.maxEntryBytes()) {
                            throw new TooLarge(name + " expands to more than " + limits.maxEntryBytes()
                                    + " bytes (the limit per file)");
                        }
                        if (total > limits.maxTotalBytes()) {
                            throw new TooLarge("the archive expands to more than " + limits.maxTotalBytes()
                                    + " bytes (the limit; config key restoreMaxBytes)");
                        }
                        out.write(buffer, 0, n);
                        if (wanted && mac != null && !isSignature) {
                            mac.update(buffer, 0, n);
                        }
                    }
                }
                if (wanted && mac != null && !isSignature) {
                    ArchiveSignature.end(mac, size);
                }
                if (wanted && isSignature) {
                    signature = Files.readAllBytes(staging.resolve(name));
                } else if (wanted) {
                    names.add(name);
                }
            }
        }
        if (entries == 0) {
            throw new IOException("no entries (empty or not a zip file)");
        }
        return new Unpacked(staging, List.copyOf(names), signature, problems);
    }
}
