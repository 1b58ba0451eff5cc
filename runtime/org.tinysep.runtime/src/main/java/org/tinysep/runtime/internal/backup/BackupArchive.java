package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import javax.crypto.Mac;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * Writes the configuration archive of {@code tinysep:backup} (docs/backup.md): a zip of the entries
 * {@link StateFiles#collect} gives, followed by the signature entry ({@link ArchiveSignature}). Written atomically
 * (temp file, {@code rw-------}, fsync, rename). Reading is {@link ArchiveUnpacker} and {@link ArchiveValidator}.
 */
final class BackupArchive {

    private BackupArchive() {
    }

    /** Writes {@code entries} and their signature to {@code target} atomically; @return the number of files */
    static int write(Path target, Map<String, byte[]> entries, ArchiveSignature key) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        AtomicFiles.createPrivateDirectories(dir);
        Path tmp = Files.createTempFile(dir, target.getFileName() + ".", ".tmp"); // rw------- on POSIX
        try {
            Mac mac = key.newMac();
            try (ZipOutputStream zip = new ZipOutputStream(Files.newOutputStream(tmp))) {
                for (Map.Entry<String, byte[]> e : entries.entrySet()) {
                    zip.putNextEntry(new ZipEntry(e.getKey()));
                    zip.write(e.getValue());
                    zip.closeEntry();
                    ArchiveSignature.begin(mac, e.getKey());
                    mac.update(e.getValue());
                    ArchiveSignature.end(mac, e.getValue().length);
                }
                zip.putNextEntry(new ZipEntry(ArchiveSignature.ENTRY));
                zip.write(key.entry(mac));
                zip.closeEntry();
            }
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE)) {
                ch.force(true);
            }
            AtomicFiles.move(tmp, target);
        } finally {
            Files.deleteIfExists(tmp);
        }
        return entries.size();
    }
}
