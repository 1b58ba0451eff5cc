package org.tinysep.device.support.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 12 item 5: state files are never left half-written. A save that fails part-way (the disk filled up while
 * writing, the process died before the rename) leaves the old file exactly as it was and no temp file behind.
 */
class AtomicFilesTest {

    @TempDir
    Path dir;

    @Test
    void aWriteThatFailsBeforeItIsCompleteLeavesTheOldFileIntact() throws Exception {
        Path house = dir.resolve("house.xml");
        AtomicFiles.write(house, "<HOUSE_ROOMS>old</HOUSE_ROOMS>".getBytes(StandardCharsets.UTF_8));

        UncheckedIOException full = assertThrows(UncheckedIOException.class, () -> AtomicFiles.write(house,
                "<HOUSE_ROOMS>new, and much longer".getBytes(StandardCharsets.UTF_8), () -> {
                    throw new UncheckedIOException(new IOException("No space left on device"));
                }));
        assertEquals("No space left on device", full.getCause().getMessage());
        assertEquals("<HOUSE_ROOMS>old</HOUSE_ROOMS>", Files.readString(house));
        assertEquals(List.of("house.xml"), names(), "no temp file left behind");

        AtomicFiles.write(house, "<HOUSE_ROOMS>new</HOUSE_ROOMS>".getBytes(StandardCharsets.UTF_8));
        assertEquals("<HOUSE_ROOMS>new</HOUSE_ROOMS>", Files.readString(house));
    }

    @Test
    void aWriteIntoAFolderThatCannotTakeTheFileLeavesTheOldFileIntact() throws Exception {
        Path house = dir.resolve("house.xml");
        AtomicFiles.write(house, "old".getBytes(StandardCharsets.UTF_8));
        boolean readOnly = dir.toFile().setWritable(false);
        try {
            if (readOnly && !Files.isWritable(dir)) { // not as root
                assertThrows(IOException.class, () -> AtomicFiles.write(house, "new".getBytes(StandardCharsets.UTF_8)));
                assertEquals("old", Files.readString(house));
            }
        } finally {
            dir.toFile().setWritable(true);
        }
        assertEquals(List.of("house.xml"), names());
    }

    private List<String> names() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
