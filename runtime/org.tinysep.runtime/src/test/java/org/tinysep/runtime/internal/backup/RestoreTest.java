package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;

/**
 * Issue 10 item 4: backup and restore on real files (docs/backup.md). A crafted archive is refused as a whole and
 * changes nothing; a restore keeps a copy of what it replaces and {@code --undo} brings it back; archives are
 * signed; the state files are private.
 */
class RestoreTest {

    static final String HOUSE = "<HOUSE_ROOMS><ROOM><UID>r-1</UID><NAME>Hall</NAME><TYPE>Hall</TYPE>"
            + "<NEIGHBORS><ROOM_UID>r-2</ROOM_UID></NEIGHBORS></ROOM><ROOM><UID>r-2</UID><NAME>Bathroom</NAME>"
            + "</ROOM></HOUSE_ROOMS>";
    static final ArchiveUnpacker.Limits LIMITS = new ArchiveUnpacker.Limits(1L << 20, 256 << 10, 100);

    @TempDir
    Path dir;
    Path var;
    Path etc;
    StateFiles files;
    BackupStoreService store;
    final List<String> calls = new ArrayList<>();
    final BackupCodec codec = new BackupCodec();

    @BeforeEach
    void home() throws IOException {
        var = dir.resolve("home/var");
        etc = Files.createDirectories(dir.resolve("home/etc"));
        Files.createDirectories(var.resolve("backup/AmicaDoor"));
        Files.write(var.resolve("backup/AmicaDoor/AmicaDoor-u-1.xml"), codec.write(BackupStoreServiceTest.device(
                "u-1", "Front door", "r-1", Instant.parse("2026-11-22T10:00:00Z"))));
        Files.writeString(var.resolve("house.xml"), HOUSE);
        Files.writeString(etc.resolve("org.tinysep.timecontroller.cfg"), "mode=REAL\nsyncPort=47100\n");
        Files.writeString(etc.resolve("org.tinysep.mailmanager.cfg"), "host=127.0.0.1\nuser=anna\npassword=s3cret\n");
        Files.writeString(etc.resolve("org.apache.felix.fileinstall-deploy.cfg"), "felix.fileinstall.dir=deploy\n");
        files = new StateFiles(var.resolve("backup"), var, etc);
        store = new BackupStoreService(var.resolve("backup"), 0, new NoEvents());
    }

    @AfterEach
    void stop() throws InterruptedException {
        store.deactivate();
    }

    private Restorer restorer() {
        return new Restorer(files, codec, LIMITS, new Restorer.Platform() {
            @Override
            public int stopApplications(List<String> problems) {
                calls.add("stop");
                return 1;
            }

            @Override
            public void flushStore() {
                calls.add("flush");
            }

            @Override
            public void reloadStore() {
                store.reload();
                calls.add("reload");
            }

            @Override
            public void startApplications(List<String> problems) {
                calls.add("start");
            }

            @Override
            public void settingsChanged(Path archive, List<String> changes) {
                calls.add("settings changed: " + String.join("; ", changes));
            }
        });
    }

    private Path backup(boolean withSecrets) throws IOException {
        Path zip = dir.resolve("config.zip");
        BackupArchive.write(zip, files.collect(true, withSecrets), ArchiveSignature.loadOrCreate(files.keyFile()));
        return zip;
    }

    /** @return the signed archive of the current state with {@code extra} entries added (null value: removed) */
    private Path signedWith(Map<String, String> extra) throws IOException {
        Map<String, byte[]> entries = new LinkedHashMap<>(files.collect(true, false));
        extra.forEach((k, v) -> {
            if (v == null) {
                entries.remove(k);
            } else {
                entries.put(k, v.getBytes(StandardCharsets.UTF_8));
            }
        });
        Path zip = dir.resolve("crafted.zip");
        BackupArchive.write(zip, entries, ArchiveSignature.loadOrCreate(files.keyFile()));
        return zip;
    }

    private Map<String, byte[]> snapshot() throws IOException {
        Map<String, byte[]> all = new LinkedHashMap<>(files.collect(false, true));
        all.put("fileinstall", Files.readAllBytes(etc.resolve("org.apache.felix.fileinstall-deploy.cfg")));
        return all;
    }

    private void assertUnchanged(Map<String, byte[]> before) throws IOException {
        Map<String, byte[]> now = snapshot();
        assertEquals(before.keySet(), now.keySet());
        before.forEach((k, v) -> assertArrayEquals(v, now.get(k), k));
        assertFalse(calls.contains("stop"), "no application was stopped");
        assertFalse(Files.exists(var.resolve("restore.staging")), "staging folder removed");
    }

    private String refused(Path zip, boolean force) throws IOException {
        Map<String, byte[]> before = snapshot();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> restorer().restore(zip, force));
        assertTrue(e.getMessage().startsWith(zip.getFileName() + " rejected, nothing changed: "), e.getMessage());
        assertUnchanged(before);
        return e.getMessage();
    }

    @Test
    void aConfigurationTinySepDoesNotOwnIsRefusedEvenWhenForcedAndSigned() throws Exception {
        String m = refused(signedWith(Map.of("etc/org.apache.felix.fileinstall-evil.cfg",
                "felix.fileinstall.dir=/tmp/evil\nfelix.fileinstall.start.level=5\n")), true);
        assertTrue(m.contains("etc/org.apache.felix.fileinstall-evil.cfg: not a configuration TinySEP owns"), m);
        assertFalse(Files.exists(etc.resolve("org.apache.felix.fileinstall-evil.cfg")));
        m = refused(signedWith(Map.of("etc/com.example.other.cfg", "x=1\n")), true);
        assertTrue(m.contains("etc/com.example.other.cfg: not a configuration TinySEP owns"), m);
    }

    @Test
    void aHouseOfTheWrongShapeIsRefusedAndTheHouseIsUnchanged() throws Exception {
        String m = refused(signedWith(Map.of("house.xml", "<HOUSE><WRONG/></HOUSE>")), false);
        assertTrue(m.contains("house.xml: not a house plan"), m);
        assertEquals(HOUSE, Files.readString(var.resolve("house.xml")));
        m = refused(signedWith(Map.of("house.xml", HOUSE.replace("<ROOM_UID>r-2", "<ROOM_UID>r-9"))), false);
        assertTrue(m.contains("house.xml: not a house plan"), "a neighbour that is no room: " + m);
        m = refused(signedWith(Map.of("house.xml", HOUSE.replace("<UID>r-2", "<UID>r-1"))), false);
        assertTrue(m.contains("house.xml: not a house plan"), "two rooms with one UID: " + m);
    }

    @Test
    void aDriversListWithAnHttpUrlOrTheWrongShapeIsRefused() throws Exception {
        String m = refused(signedWith(Map.of("drivers.xml", "<DRIVERS_LIST><DRIVER><FILE_PATH>"
                + "http://example.org/evil.jar</FILE_PATH></DRIVER></DRIVERS_LIST>")), false);
        assertTrue(m.contains("drivers.xml: DRIVER #1: FILE_PATH http://example.org/evil.jar uses http:"), m);
        m = refused(signedWith(Map.of("drivers.xml", "<DRIVERS><X/></DRIVERS>")), false);
        assertTrue(m.contains("drivers.xml: not a drivers list"), m);
        assertEquals(null, ArchiveValidator.locationProblem("https://example.org/a.jar"));
        assertEquals(null, ArchiveValidator.locationProblem("file:/opt/tinysep/a.jar"));
        assertEquals(null, ArchiveValidator.locationProblem("bundles/5-apps/a.jar"));
    }

    @Test
    void duplicateEntriesAreRefused() throws Exception {
        Path zip = dir.resolve("dup.zip");
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(zip))) {
            out.putNextEntry(new ZipEntry("house.xml"));
            out.write(HOUSE.getBytes(StandardCharsets.UTF_8));
            out.putNextEntry(new ZipEntry("house.xmX"));
            out.write("<HOUSE_ROOMS/>".getBytes(StandardCharsets.UTF_8));
            out.closeEntry();
        }
        // ZipOutputStream refuses a repeated name: rename the second entry in its headers
        String bytes = new String(Files.readAllBytes(zip), StandardCharsets.ISO_8859_1);
        Files.write(zip, bytes.replace("house.xmX", "house.xml").getBytes(StandardCharsets.ISO_8859_1));
        String m = refused(zip, true);
        assertTrue(m.contains("house.xml: appears more than once"), m);
    }

    @Test
    void anArchiveExpandingPastTheCapIsRefusedWhileStreamingWithoutFillingTheHeap() throws Exception {
        Path bomb = dir.resolve("bomb.zip");
        byte[] zeros = new byte[200 << 10]; // 40 entries of 200 KiB: each under the per-file cap, 8 MiB in all
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(bomb))) {
            for (int i = 0; i < 40; i++) {
                out.putNextEntry(new ZipEntry("backup/AmicaDoor/AmicaDoor-bomb-" + i + ".xml"));
                out.write(zeros);
                out.closeEntry();
            }
        }
        assertTrue(Files.size(bomb) < 16 << 10, "a few KB: " + Files.size(bomb));
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long before = threads.getCurrentThreadAllocatedBytes();
        String m = refused(bomb, true);
        long allocated = threads.getCurrentThreadAllocatedBytes() - before;
        System.out.printf("bomb of %d bytes (8 MiB inflated) refused; %d KiB allocated while refusing it%n",
                Files.size(bomb), allocated >> 10);
        assertTrue(m.contains("the archive expands to more than " + LIMITS.maxTotalBytes() + " bytes"), m);
        assertTrue(allocated < 4 << 20, "streamed, not held: " + allocated + " bytes allocated");
        Path one = dir.resolve("one.zip");
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(one))) {
            out.putNextEntry(new ZipEntry("house.xml"));
            out.write(new byte[300 << 10]);
            out.closeEntry();
        }
        assertTrue(refused(one, true).contains("house.xml expands to more than 262144 bytes (the limit per file)"));
    }

    @Test
    void unsignedForeignAndAlteredArchivesAreRefusedUnlessForced() throws Exception {
        Path signed = backup(false);
        Path unsigned = dir.resolve("unsigned.zip");
        Path altered = dir.resolve("altered.zip");
        try (ZipFile in = new ZipFile(signed.toFile());
                ZipOutputStream u = new ZipOutputStream(Files.newOutputStream(unsigned));
                ZipOutputStream a = new ZipOutputStream(Files.newOutputStream(altered))) {
            for (ZipEntry e : java.util.Collections.list(in.entries())) {
                byte[] bytes = in.getInputStream(e).readAllBytes();
                if (!e.getName().equals(ArchiveSignature.ENTRY)) {
                    u.putNextEntry(new ZipEntry(e.getName()));
                    u.write(bytes);
                }
                a.putNextEntry(new ZipEntry(e.getName()));
                a.write(e.getName().equals("house.xml") ? "<HOUSE_ROOMS/>".getBytes(StandardCharsets.UTF_8) : bytes);
            }
        }
        assertTrue(refused(unsigned, false).contains("the archive is not signed"));
        assertTrue(refused(altered, false).contains("the archive was changed after this installation signed it"));
        Files.writeString(files.keyFile(), "00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff\n");
        assertTrue(refused(signed, false).contains("the archive was signed by another installation"));
        String out = restorer().restore(signed, true);
        assertTrue(out.contains("restored although the archive was signed by another installation"), out);
    }

    @Test
    void aRestoreKeepsACopyOfTheStateItReplacesAndUndoBringsItBack() throws Exception {
        Path zip = backup(false);
        Map<String, byte[]> original = snapshot();
        // the state changes after the backup: another house, a renamed door, a new cfg
        Files.writeString(var.resolve("house.xml"), HOUSE.replace("Bathroom", "Bath"));
        store.save(BackupStoreServiceTest.device("u-1", "Renamed", "r-2", Instant.parse("2026-11-23T10:00:00Z")));
        store.save(BackupStoreServiceTest.device("u-2", "New", "r-2", Instant.parse("2026-11-23T10:00:00Z")));
        assertTrue(store.flush(java.time.Duration.ofSeconds(5)));
        Files.writeString(etc.resolve("org.tinysep.inactivity.cfg"), "limitMinutes=30\n");
        Map<String, byte[]> changed = snapshot();

        String out = restorer().restore(zip, false);
        assertTrue(out.startsWith("restored ") && out.contains("tinysep:restore --undo"), out);
        assertEquals(List.of("stop", "flush", "reload", "start"), calls);
        assertEquals(HOUSE, Files.readString(var.resolve("house.xml")));
        assertEquals("Front door", store.find("u-1").orElseThrow().name());
        assertTrue(store.find("u-2").isEmpty());
        assertTrue(Files.readString(etc.resolve("org.tinysep.mailmanager.cfg")).contains("password=s3cret"),
                "the password here is kept although the archive has none");
        Path copy;
        try (var list = Files.list(files.undoFolder())) {
            copy = list.findFirst().orElseThrow();
        }
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(copy)));

        out = restorer().undo();
        assertTrue(out.startsWith("undone: brought back "), out);
        Map<String, byte[]> undone = snapshot();
        assertEquals(changed.keySet(), undone.keySet());
        changed.forEach((k, v) -> assertArrayEquals(v, undone.get(k), k));
        assertEquals("Renamed", store.find("u-1").orElseThrow().name());
        assertEquals("New", store.find("u-2").orElseThrow().name());
        assertFalse(original.keySet().contains("etc/org.tinysep.inactivity.cfg"));
    }

    @Test
    void aFailureWhileReplacingPutsThePreviousStateBack() throws Exception {
        Path zip = signedWith(Map.of("house.xml", HOUSE.replace("Bathroom", "Bath"),
                "etc/org.tinysep.inactivity.cfg", "limitMinutes=30\n"));
        // the cfg cannot be written: a folder (not empty) stands where the file goes
        Files.createDirectories(etc.resolve("org.tinysep.inactivity.cfg/in-the-way"));
        store.save(BackupStoreServiceTest.device("u-2", "New", "r-2", Instant.parse("2026-11-23T10:00:00Z")));
        assertTrue(store.flush(java.time.Duration.ofSeconds(5)));
        Map<String, byte[]> before = snapshot();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> restorer().restore(zip, false));
        assertTrue(e.getMessage().startsWith("the restore failed while replacing files (")
                && e.getMessage().endsWith("the previous state was put back"), e.getMessage());
        Map<String, byte[]> after = snapshot();
        assertEquals(before.keySet(), after.keySet());
        before.forEach((k, v) -> assertArrayEquals(v, after.get(k), k));
        assertEquals("New", store.find("u-2").orElseThrow().name(), "the store reads the folder put back");
        assertEquals(List.of("stop", "flush", "reload", "reload", "start"), calls);
    }

    @Test
    void aRestoreNeverChangesTheTimeControllersModeAndSaysSo() throws Exception {
        Path zip = signedWith(Map.of("etc/org.tinysep.timecontroller.cfg", "mode=EXTERNAL\nsyncPort=47200\n"));
        String out = restorer().restore(zip, false);
        assertTrue(out.contains("org.tinysep.timecontroller.cfg: kept this installation's mode (REAL); the archive's "
                + "EXTERNAL was not applied"), out);
        String cfg = Files.readString(etc.resolve("org.tinysep.timecontroller.cfg"));
        assertTrue(cfg.contains("syncPort=47200") && cfg.contains("mode=REAL") && !cfg.contains("EXTERNAL"), cfg);
    }

    @Test
    void backupsHoldOnlyOwnedCfgsWithoutPasswordsAndSecretsOnlyWhenAsked() throws Exception {
        backup(false); // makes the key, and so the secrets folder
        Files.writeString(files.secrets().resolve("smtp.password"), "s3cret");
        Path zip = backup(false);
        Map<String, String> entries = new LinkedHashMap<>();
        try (ZipFile z = new ZipFile(zip.toFile())) {
            for (ZipEntry e : java.util.Collections.list(z.entries())) {
                entries.put(e.getName(), new String(z.getInputStream(e).readAllBytes(), StandardCharsets.UTF_8));
            }
        }
        assertEquals(List.of("backup/AmicaDoor/AmicaDoor-u-1.xml", "house.xml", "etc/org.tinysep.mailmanager.cfg",
                "etc/org.tinysep.timecontroller.cfg", ArchiveSignature.ENTRY), List.copyOf(entries.keySet()));
        assertEquals("host=127.0.0.1\nuser=anna\n", entries.get("etc/org.tinysep.mailmanager.cfg"));
        assertFalse(entries.values().stream().anyMatch(v -> v.contains("s3cret")), "no password in the archive");
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(zip)));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(files.keyFile())));
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(files.secrets())),
                "secrets folder");
        try (ZipFile z = new ZipFile(backup(true).toFile())) {
            assertTrue(z.getEntry("secrets/smtp.password") != null);
            assertTrue(z.getEntry("secrets/backup.key") == null, "the key never leaves");
        }
    }

    @Test
    void stateFilesAreWrittenPrivate() throws Exception {
        Path house = var.resolve("fresh/house.xml");
        org.tinysep.device.support.files.AtomicFiles.write(house, HOUSE.getBytes(StandardCharsets.UTF_8));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(house)));
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(house.getParent())));
        store.save(BackupStoreServiceTest.device("u-9", "x", "r-1", Instant.parse("2026-11-23T10:00:00Z")));
        assertTrue(store.flush(java.time.Duration.ofSeconds(5)));
        Path file = var.resolve("backup/BusRadioAmicaUdp/BusRadioAmicaUdp-u-9.xml");
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file.getParent())));
    }

    /** An event log that keeps nothing. */
    static final class NoEvents implements EventLog {
        @Override
        public void record(EventKind kind, String origin, String message) {
        }

        @Override
        public List<EventEntry> recent(int max) {
            return List.of();
        }
    }

    @Test
    void aForcedRestoreListsEverySettingItChangesOldToNew() throws Exception { // issue 25, item 3
        Files.writeString(etc.resolve("org.tinysep.inactivity.cfg"), "limitMinutes=30\n");
        Path zip = signedWith(Map.of("etc/org.tinysep.inactivity.cfg", "limitMinutes=5256000\n",
                "etc/org.tinysep.mailmanager.cfg", "host=mail.evil.test\nuser=anna\n"));
        String out = restorer().restore(zip, true);
        assertTrue(out.contains("settings changed (old → new), "), out);
        assertTrue(out.contains("  org.tinysep.inactivity.cfg limitMinutes: 30 → 5256000\n"), out);
        assertTrue(out.contains("  org.tinysep.mailmanager.cfg host: 127.0.0.1 → mail.evil.test"), out);
        assertFalse(out.contains("s3cret"), out);
        assertTrue(calls.stream().anyMatch(c -> c.startsWith("settings changed: org.tinysep.inactivity.cfg "
                + "limitMinutes: 30 → 5256000")), calls.toString());
        assertTrue(restorer().restore(backup(false), false).contains("no setting in etc/ changed"));
    }
}
