package org.tinysep.itests.backup;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipOutputStream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.tinysep.tools.process.PlatformProcess;
import org.tinysep.tools.process.Ports;

/**
 * Issue 10 items 4 and 6 on the real distribution (a process, driven through its shell as a user does): the state
 * folder and the files the platform writes are private; a backup holds no password; crafted archives — a FileInstall
 * configuration, a house of the wrong shape, a zip bomb, an {@code http:} driver — are refused and change nothing;
 * a restore can be undone.
 */
public class CraftedArchiveTest {

    private static final String PASSWORD = "Secret-4711";

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    /** Item 6: the state folder, the house, backup files, archives and logs are private; backups hold no password. */
    @Test
    public void stateFilesArePrivateAndBackupsHoldNoPassword() throws Exception {
        Path home = home();
        Path var = home.resolve("var");
        try (PlatformProcess p = started(home)) {
            Path zip = backup(p, home);
            assertEquals("state folder", "rwx------", mode(var));
            String log;
            try (Stream<Path> list = Files.list(home)) { // platform-<n>.log: n counts launches in this JVM
                log = Files.readString(list.filter(f -> f.getFileName().toString().startsWith("platform-"))
                        .findFirst().orElseThrow());
            }
            assertTrue("a plain warning", log.contains("was open to other users"));
            assertEquals("house.xml", "rw-------", mode(var.resolve("house.xml")));
            assertEquals("backup archive", "rw-------", mode(zip));
            for (Path f : files(var.resolve("backup"))) {
                assertEquals(f.toString(), Files.isDirectory(f) ? "rwx------" : "rw-------", mode(f));
            }
            List<Path> logs = files(var.resolve("log"));
            assertTrue("log history written", logs.size() > 1);
            for (Path f : logs) {
                assertEquals(f.toString(), Files.isDirectory(f) ? "rwx------" : "rw-------", mode(f));
            }
            Map<String, byte[]> archive = read(zip);
            assertTrue(archive.keySet().toString(), archive.containsKey("etc/org.tinysep.mailmanager.cfg"));
            assertFalse("no password in the backup", archive.values().stream()
                    .anyMatch(v -> new String(v, StandardCharsets.UTF_8).contains(PASSWORD)));
            assertEquals(0, p.stop(Duration.ofSeconds(60)));
        }
    }

    /**
     * Item 4: a FileInstall cfg, a house of the wrong shape, an {@code http:} driver and a zip bomb are refused
     * through the shell and change nothing; a restore keeps the state it replaces and {@code --undo} brings it back.
     */
    @Test
    public void craftedArchivesAreRefusedAndARestoreCanBeUndone() throws Exception {
        Path home = home();
        Path var = home.resolve("var");
        try (PlatformProcess p = started(home)) {
            Path zip = backup(p, home);
            Map<String, byte[]> archive = read(zip);

            // item 4: crafted archives are refused, nothing changes
            byte[] house = Files.readAllBytes(var.resolve("house.xml"));
            Map<String, byte[]> evil = new LinkedHashMap<>(archive);
            evil.put("etc/org.apache.felix.fileinstall-evil.cfg", ("felix.fileinstall.dir=" + tmp.newFolder("evil")
                    + "\n").getBytes(StandardCharsets.UTF_8));
            refused(p, write(home.resolve("evil.zip"), evil),
                    "etc/org.apache.felix.fileinstall-evil.cfg: not a configuration TinySEP owns");
            assertFalse(Files.exists(home.resolve("etc/org.apache.felix.fileinstall-evil.cfg")));

            Map<String, byte[]> wrongHouse = new LinkedHashMap<>(archive);
            wrongHouse.put("house.xml", "<HOUSE><WRONG/></HOUSE>".getBytes(StandardCharsets.UTF_8));
            refused(p, write(home.resolve("house.zip"), wrongHouse), "house.xml: not a house plan");
            assertTrue("house unchanged", java.util.Arrays.equals(house, Files.readAllBytes(var.resolve("house.xml"))));

            Map<String, byte[]> http = new LinkedHashMap<>(archive);
            http.put("drivers.xml", ("<DRIVERS_LIST><DRIVER><FILE_PATH>http://127.0.0.1:9/evil.jar</FILE_PATH>"
                    + "</DRIVER></DRIVERS_LIST>").getBytes(StandardCharsets.UTF_8));
            refused(p, write(home.resolve("http.zip"), http), "uses http: — only file: and https: URLs are accepted");

            Path bomb = home.resolve("bomb.zip");
            try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(bomb))) {
                byte[] zeros = new byte[(4 << 20) - 1]; // each entry under the old 4 MiB limit; 80 MiB in all
                for (int i = 0; i < 20; i++) {
                    out.putNextEntry(new ZipEntry("backup/AmicaDoor/AmicaDoor-bomb-" + i + ".xml"));
                    out.write(zeros);
                    out.closeEntry();
                }
            }
            System.out.println("zip bomb: " + Files.size(bomb) + " bytes, 80 MiB inflated");
            refused(p, bomb, "the archive expands to more than " + (64 << 20) + " bytes");
            expect(p, "tinysep:rooms", "Pantry"); // the platform still answers, its house unchanged

            // item 4: a restore keeps the state it replaces; --undo brings it back
            expect(p, "tinysep:room-remove Pantry", "");
            expect(p, "tinysep:room-add Attic storage --new-type", "added Attic");
            byte[] beforeRestore = Files.readAllBytes(var.resolve("house.xml"));
            expect(p, "tinysep:restore " + zip, "restored ");
            assertTrue("Pantry back", String.join("\n", p.command("tinysep:rooms")).contains("Pantry"));
            expect(p, "tinysep:restore --undo", "undone: brought back ");
            String rooms = String.join("\n", p.command("tinysep:rooms"));
            assertTrue(rooms, rooms.contains("Attic") && !rooms.contains("Pantry"));
            assertTrue("house as before the restore",
                    java.util.Arrays.equals(beforeRestore, Files.readAllBytes(var.resolve("house.xml"))));

            // an unsigned archive: refused, saying why; restored with --force after every other check
            Map<String, byte[]> unsigned = new LinkedHashMap<>(archive);
            unsigned.remove("tinysep-signature.txt");
            Path plain = write(home.resolve("unsigned.zip"), unsigned);
            refused(p, plain, "the archive is not signed");
            expect(p, "tinysep:restore --force " + plain, "restored although the archive is not signed");
            expect(p, "tinysep:rooms", "Pantry");
            assertEquals(0, p.stop(Duration.ofSeconds(60)));
        }
    }

    /** A home for flat A whose state folder others can read and whose Mail Manager has a password. */
    private Path home() throws IOException {
        FlatHome flat = new FlatHome(tmp.newFolder("home").toPath());
        Files.setPosixFilePermissions(flat.home.resolve("var"), PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.writeString(flat.home.resolve("etc/org.tinysep.mailmanager.cfg"), "host=127.0.0.1\nport="
                + Ports.freeUdp() + "\nsecurity=NONE\nuser=anna\npassword=" + PASSWORD
                + "\nfrom=tinysep@example.org\nrecipients=carer@example.org\n");
        return flat.home;
    }

    /** @return the platform, started, with a room added (so House Information has written the house) */
    private static PlatformProcess started(Path home) throws Exception {
        PlatformProcess p = Platforms.start(home);
        try {
            RestartRestoresEverythingTest.await(p, () -> p.command("tinysep:drivers").toString(),
                    s -> s.contains("TimeController") && s.contains("HouseInformation"), "drivers up");
            expect(p, "tinysep:room-add Pantry storage --new-type", "added Pantry");
            return p;
        } catch (Exception | AssertionError e) {
            p.close();
            throw e;
        }
    }

    /** Writes a backup with {@code tinysep:backup}; @return the archive, {@code <home>/config.zip} */
    private static Path backup(PlatformProcess p, Path home) {
        Path zip = home.resolve("config.zip");
        expect(p, "tinysep:backup " + zip, "wrote ");
        return zip;
    }

    private static void refused(PlatformProcess p, Path zip, String reason) {
        String out = String.join("\n", p.command("tinysep:restore " + zip));
        assertTrue(out, out.contains("rejected, nothing changed") && out.contains(reason));
    }

    private static void expect(PlatformProcess p, String command, String expected) {
        String out = String.join("\n", p.command(command));
        assertTrue(command + " -> " + out, out.contains(expected));
    }

    private static String mode(Path f) throws IOException {
        return PosixFilePermissions.toString(Files.getPosixFilePermissions(f));
    }

    private static List<Path> files(Path dir) throws IOException {
        try (Stream<Path> walk = Files.walk(dir)) {
            return walk.toList();
        }
    }

    private static Map<String, byte[]> read(Path zip) throws IOException {
        Map<String, byte[]> out = new LinkedHashMap<>();
        try (ZipFile z = new ZipFile(zip.toFile())) {
            for (ZipEntry e : java.util.Collections.list(z.entries())) {
                out.put(e.getName(), z.getInputStream(e).readAllBytes());
            }
        }
        return out;
    }

    /** @return {@code zip} holding {@code entries} as a third party would make it (the old signature, if any, kept) */
    private static Path write(Path zip, Map<String, byte[]> entries) throws IOException {
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(zip))) {
            for (Map.Entry<String, byte[]> e : entries.entrySet()) {
                out.putNextEntry(new ZipEntry(e.getKey()));
                out.write(e.getValue());
                out.closeEntry();
            }
        }
        return zip;
    }
}
