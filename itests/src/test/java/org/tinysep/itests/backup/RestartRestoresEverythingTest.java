package org.tinysep.itests.backup;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.TreeMap;
import java.util.function.Supplier;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.tinysep.simulator.cli.Run;
import org.tinysep.tools.process.PlatformProcess;

/**
 * docs/acceptance.md scenario 6 (thesis 3.7): the real distribution runs as its own process with the simulated flat A (the
 * real simulator over UDP in lock-step); the user adds a room, places devices in other rooms, changes a parameter and
 * names one device; the framework stops (end of the shell's input: a clean stop) and starts again with the same home.
 * Before any packet arrives (the simulator does not run again) {@code tinysep:devices} shows the same devices,
 * rooms, settings, node data, last seen times and connections (live readings and the status excepted, see
 * {@link DeviceListing}). Pax Exam cannot restart its own framework, so this test starts the distribution as a
 * process, as a user does. A torn file planted before the restart is reported and moved aside while every other
 * file restores; then {@code tinysep:backup} and {@code tinysep:restore} are exercised.
 */
public class RestartRestoresEverythingTest {

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    @Test
    public void restartBringsBackDevicesRoomsParametersAndConnectionsBeforeAnyPacket() throws Exception {
        FlatHome flat = new FlatHome(tmp.newFolder("home").toPath());
        TreeMap<String, List<String>> before;
        String door;
        List<String> rooms;
        List<String> lastPackets;
        try (PlatformProcess p = Platforms.start(flat.home)) {
            await(p, () -> p.command("tinysep:drivers").toString(), s -> s.contains("TimeController")
                    && s.contains("BusRadioAmicaUdp") && s.contains("BusRadioSunSpot"), "drivers up");
            Run.simulate(flat.simulatorArgs("06:00", "06:50"));
            TreeMap<String, List<String>> placed = stable(p);
            door = uidOf(placed, "AmicaDoor");
            String movement = uidOf(placed, "AmicaMovement");
            configure(p, "tinysep:set " + movement + " room Kitchen", "room=Kitchen");
            configure(p, "tinysep:room-add Pantry storage --new-type", "added Pantry");
            configure(p, "tinysep:set " + uidOf(placed, "AmicaWindow") + " room Pantry", "room=Pantry");
            configure(p, "tinysep:set " + door + " kind INNER", "kind=INNER");
            configure(p, "tinysep:set " + door + " name \"Front door (tested)\"", "Front door (tested)");
            before = stable(p);
            rooms = p.command("tinysep:rooms");
            lastPackets = p.command("tinysep:packets 5");
            System.out.println("before the restart:\n" + DeviceListing.render(before));
            assertTrue(DeviceListing.render(before).contains("kind=INNER"));
            assertTrue(before.size() > 40);
            assertEquals("clean stop", 0, p.stop(Duration.ofSeconds(60)));
        }
        long backups;
        try (var files = Files.walk(flat.home.resolve("var/backup"))) {
            backups = files.filter(f -> f.toString().endsWith(".xml")).count();
        }
        System.out.println("backup files: " + backups + " in " + flat.home.resolve("var/backup"));
        assertTrue(Files.isRegularFile(flat.home.resolve("var/backup/AmicaDoor/AmicaDoor-" + door + ".xml")));
        Path torn = flat.home.resolve("var/backup/AmicaDoor/AmicaDoor-0000dead-torn.xml");
        Files.writeString(torn, "<backup kind=\"DEVICE\"><uid>0000dead-torn</uid><name>half a fi");
        try (PlatformProcess p = Platforms.start(flat.home)) {
            TreeMap<String, List<String>> after = stable(p);
            String log = String.join("\n", p.command("tinysep:log 500"));
            assertTrue(log, log.contains("PROBLEM") && log.contains("damaged backup file AmicaDoor-0000dead-torn.xml"));
            assertTrue("moved aside", !Files.exists(torn) && Files.list(flat.home.resolve("var/backup/damaged"))
                    .anyMatch(f -> f.getFileName().toString().startsWith("AmicaDoor_AmicaDoor-0000dead-torn.xml.")));
            System.out.println("after the restart:\n" + DeviceListing.render(after));
            assertEquals(DeviceListing.render(before), DeviceListing.render(after));
            assertEquals("rooms and their devices", byRoom(rooms), byRoom(p.command("tinysep:rooms")));
            // the packet log's history survives the restart (docs/logs.md): its newest entries are those of before
            assertEquals("no packet arrived after the restart", lastPackets, p.command("tinysep:packets 5"));
            backupAndRestore(p, flat.home, door, before);
            assertEquals(0, p.stop(Duration.ofSeconds(60)));
        }
    }

    /**
     * {@code tinysep:backup} writes an archive; a later change is undone by {@code tinysep:restore} of it; a damaged
     * archive is rejected and changes nothing.
     */
    private static void backupAndRestore(PlatformProcess p, Path home, String door,
            TreeMap<String, List<String>> expected) throws Exception {
        Path zip = home.resolve("config.zip");
        configure(p, "tinysep:backup " + zip, "wrote ");
        configure(p, "tinysep:set " + door + " name Renamed", "name=Renamed");
        Path bad = home.resolve("bad.zip");
        try (var out = new java.util.zip.ZipOutputStream(Files.newOutputStream(bad))) {
            out.putNextEntry(new java.util.zip.ZipEntry("backup/AmicaDoor/AmicaDoor-x.xml"));
            out.write("<backup kind=\"DEVICE\"><uid>x</uid><name>torn".getBytes());
            out.closeEntry();
        }
        configure(p, "tinysep:restore " + bad, "rejected, nothing changed");
        configure(p, "tinysep:devices", "\"Renamed\"");
        configure(p, "tinysep:restore " + zip, "restored ");
        TreeMap<String, List<String>> restored = stable(p);
        assertEquals(DeviceListing.render(expected), DeviceListing.render(restored));
    }

    /** {@code tinysep:rooms} with each room's devices sorted (the DEVICES column lists them in no set order). */
    private static List<String> byRoom(List<String> table) {
        int col = table.get(0).indexOf("DEVICES");
        return table.stream().map(l -> l.length() <= col ? l : l.substring(0, col)
                + String.join(", ", new java.util.TreeSet<>(List.of(l.substring(col).split(", "))))).toList();
    }

    private static void configure(PlatformProcess p, String command, String expected) {
        String out = String.join("\n", p.command(command));
        assertTrue(command + " -> " + out, out.contains(expected));
    }

    private static String uidOf(TreeMap<String, List<String>> blocks, String type) {
        return blocks.values().stream().filter(b -> b.get(0).split(" ")[1].equals(type))
                .map(b -> b.get(0).split(" ")[0]).findFirst()
                .orElseThrow(() -> new AssertionError("no " + type + " device in\n" + DeviceListing.render(blocks)));
    }

    /** Polls {@code tinysep:devices} until two listings 1 s apart are equal (at most 60 s). */
    static TreeMap<String, List<String>> stable(PlatformProcess p) throws InterruptedException {
        TreeMap<String, List<String>> last = null;
        long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        while (System.nanoTime() < deadline) {
            TreeMap<String, List<String>> now = DeviceListing.of(p.command("tinysep:devices"));
            if (now.equals(last) && !now.isEmpty()) {
                return now;
            }
            last = now;
            Thread.sleep(1000);
        }
        throw new AssertionError("tinysep:devices did not settle within 60 s:\n" + DeviceListing.render(last));
    }

    static void await(PlatformProcess p, Supplier<String> probe, java.util.function.Predicate<String> ok,
            String what) throws InterruptedException {
        long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        String last = "";
        while (System.nanoTime() < deadline) {
            last = probe.get();
            if (ok.test(last)) {
                return;
            }
            Thread.sleep(200);
        }
        throw new AssertionError("timed out waiting for " + what + "; last: " + last);
    }
}
