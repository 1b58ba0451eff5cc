package org.tinysep.device.support.files;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
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
}
