package org.tinysep.device.support.files;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicBatchTest {

    @TempDir
    Path dir;

    @Test
    void beforeTheCommitEveryTargetKeepsItsOldContentAndAfterItEveryTargetHasItsNewOne() throws Exception {
        // a kill before the commit (issue 14: a SIGKILL may lose what was not written, never leave a half file)
        Path a = dir.resolve("d/a.xml");
        Files.createDirectories(a.getParent());
        Files.writeString(a, "old a");
        Path b = dir.resolve("d/b.xml");
        AtomicBatch batch = new AtomicBatch();
        batch.write(a, "new a".getBytes(StandardCharsets.UTF_8));
        batch.write(b, "new b".getBytes(StandardCharsets.UTF_8));
        assertEquals("old a", Files.readString(a), "not replaced before the commit");
        assertFalse(Files.exists(b), "not there before the commit");
        batch.commit();
        assertArrayEquals("new a".getBytes(StandardCharsets.UTF_8), Files.readAllBytes(a));
        assertEquals("new b", Files.readString(b));
        try (Stream<Path> files = Files.list(a.getParent())) {
            assertEquals(2, files.count(), "no temp file left");
        }
        assertEquals(1, batch.foldersSynced());
        assertEquals(2, batch.filesCommitted());
        assertTrue(batch.failures().isEmpty());
    }

    /** The temp file is created and written through one open (issue 29): still private, and in place after the commit. */
    @Test
    void aTempFileIsPrivateFromItsCreationAndReplacesAnExistingTarget() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(
                java.nio.file.FileSystems.getDefault().supportedFileAttributeViews().contains("posix"));
        Path a = dir.resolve("a.xml");
        Files.writeString(a, "old content, longer than the new one");
        AtomicBatch batch = new AtomicBatch();
        batch.write(a, "new".getBytes(StandardCharsets.UTF_8));
        try (Stream<Path> files = Files.list(dir)) {
            Path tmp = files.filter(f -> f.toString().endsWith(".tmp")).findFirst().orElseThrow();
            assertEquals("rw-------", java.nio.file.attribute.PosixFilePermissions.toString(
                    Files.getPosixFilePermissions(tmp)), tmp.toString());
        }
        batch.commit();
        assertEquals("new", Files.readString(a));
        assertEquals("rw-------", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(a)));
    }

    @Test
    void aDeleteAskedAfterAWriteHappensAfterItsRename() throws Exception {
        Path old = dir.resolve("old.xml");
        Files.writeString(old, "old");
        Path now = dir.resolve("new.xml");
        AtomicBatch batch = new AtomicBatch();
        batch.write(now, "moved".getBytes(StandardCharsets.UTF_8));
        batch.delete(old);
        assertTrue(Files.exists(old), "the old file stays until the new one is in place");
        batch.commit();
        assertFalse(Files.exists(old));
        assertEquals("moved", Files.readString(now));
    }

    /**
     * Issue 29: a stop saving 2,500 device backups took 8.5 s, each force waiting for a journal commit of its own. On
     * a slow disk (every force takes 20 ms) the forces of a commit run several at once: the most at once is counted.
     */
    @Test
    void theForcesOfManyFilesAreMadeSeveralAtOnce() throws Exception {
        AtomicInteger now = new AtomicInteger();
        AtomicInteger most = new AtomicInteger();
        AtomicInteger forces = new AtomicInteger();
        AtomicBatch batch = new AtomicBatch(tmp -> {
            most.accumulateAndGet(now.incrementAndGet(), Math::max);
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            forces.incrementAndGet();
            now.decrementAndGet();
        });
        for (int i = 0; i < 64; i++) {
            batch.write(dir.resolve("d/f" + i + ".xml"), ("content " + i).getBytes(StandardCharsets.UTF_8));
        }
        batch.commit();
        assertEquals(64, forces.get(), "every file forced once");
        assertEquals(AtomicBatch.FORCERS, most.get(), "forces made at once");
        assertEquals(64, batch.filesCommitted());
        assertEquals("content 63", Files.readString(dir.resolve("d/f63.xml")));
        assertTrue(batch.failures().isEmpty());
    }

    @Test
    void aFileThatCannotBeForcedKeepsItsOldContentAndTheOthersAreCommitted() throws Exception {
        Path bad = dir.resolve("d/f3.xml");
        Files.createDirectories(bad.getParent());
        Files.writeString(bad, "old");
        AtomicBatch batch = new AtomicBatch(tmp -> {
            if (tmp.getFileName().toString().startsWith("f3.xml.")) {
                throw new IOException("disk error");
            }
        });
        for (int i = 0; i < 10; i++) {
            batch.write(dir.resolve("d/f" + i + ".xml"), "new".getBytes(StandardCharsets.UTF_8));
        }
        batch.commit();
        assertEquals("old", Files.readString(bad));
        assertEquals("new", Files.readString(dir.resolve("d/f9.xml")));
        assertEquals(java.util.Set.of(bad), batch.failures().keySet());
        try (Stream<Path> files = Files.list(bad.getParent())) {
            assertEquals(10, files.count(), "no temp file left");
        }
    }
}
