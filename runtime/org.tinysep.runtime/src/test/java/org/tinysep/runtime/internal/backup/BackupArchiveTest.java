package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The configuration archive: what goes in, and that a bad archive is refused as a whole. */
class BackupArchiveTest {

    @TempDir
    Path dir;
    private final BackupCodec codec = new BackupCodec();

    @Test
    void theArchiveHoldsBackupsHouseDriversAndCfgFilesButNotDamagedOnes() throws Exception {
        Path var = dir.resolve("var");
        Path root = var.resolve("backup");
        byte[] door = codec.write(BackupStoreServiceTest.device("u-1", "Door", "r", Instant.parse("2026-11-22T10:00:00Z")));
        Files.createDirectories(root.resolve("AmicaDoor"));
        Files.write(root.resolve("AmicaDoor/AmicaDoor-u-1.xml"), door);
        Files.createDirectories(root.resolve("damaged"));
        Files.writeString(root.resolve("damaged/AmicaDoor_x.xml.20261122T100000.000Z"), "<torn");
        Files.writeString(var.resolve("house.xml"), "<rooms/>");
        Path etc = Files.createDirectories(dir.resolve("etc"));
        Files.writeString(etc.resolve("org.tinysep.amica.busradio.udp.cfg"), "port=47011\n");
        Files.writeString(etc.resolve("notes.txt"), "not a cfg");

        Path zip = dir.resolve("out.zip");
        assertEquals(3, BackupArchive.write(zip, root, var, etc));

        Map<String, byte[]> read = BackupArchive.read(zip, codec);
        assertEquals(List.of("backup/AmicaDoor/AmicaDoor-u-1.xml", "house.xml", "etc/org.tinysep.amica.busradio.udp.cfg"),
                List.copyOf(read.keySet()));
        assertArrayEquals(door, read.get("backup/AmicaDoor/AmicaDoor-u-1.xml"));
    }

    @Test
    void anArchiveWithAnyBadEntryIsRejectedWithEveryReason() throws Exception {
        Path zip = zip(Map.of("backup/AmicaDoor/AmicaDoor-u-1.xml", "<backup kind=\"DEVICE\"><uid>u-1</uid>",
                "../../etc/passwd", "root", "house.xml", "<rooms><room></rooms>",
                "backup/AmicaDoor/AmicaDoor-u-2.xml", "<!DOCTYPE x [<!ENTITY e SYSTEM \"file:///etc/passwd\">]><x>&e;</x>"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> BackupArchive.read(zip, codec));
        assertTrue(e.getMessage().startsWith("bad.zip rejected, nothing changed: "), e.getMessage());
        for (String name : List.of("AmicaDoor-u-1.xml", "AmicaDoor-u-2.xml", "../../etc/passwd", "house.xml")) {
            assertTrue(e.getMessage().contains(name), () -> name + " not named in: " + e.getMessage());
        }
    }

    @Test
    void somethingThatIsNotAZipOrHoldsNoBackupsIsRejected() throws Exception {
        Path notZip = Files.writeString(dir.resolve("x.zip"), "hello");
        assertThrows(IllegalArgumentException.class, () -> BackupArchive.read(notZip, codec));
        Path onlyCfg = zip(Map.of("etc/a.cfg", "x=1"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> BackupArchive.read(onlyCfg, codec))
                .getMessage().contains("no backup/ files"));
    }

    private Path zip(Map<String, String> entries) throws IOException {
        Path zip = dir.resolve("bad.zip");
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(zip))) {
            for (Map.Entry<String, String> e : entries.entrySet()) {
                out.putNextEntry(new ZipEntry(e.getKey()));
                out.write(e.getValue().getBytes(StandardCharsets.UTF_8));
                out.closeEntry();
            }
        }
        return zip;
    }
}
