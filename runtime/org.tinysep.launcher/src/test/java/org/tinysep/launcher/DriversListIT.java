package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.launcher.TestDistribution.await;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;

/**
 * The drivers list in the real distribution, across restarts: the state folder ({@code --var}) outside the
 * distribution, the list seeded from {@code bundles/5-apps}, reload/enable/disable, shell installs that survive a
 * restart, a broken file moved aside while the platform keeps its previous list.
 */
class DriversListIT extends StateFolderFixture {

    private static final Duration WAIT = Duration.ofSeconds(15);
    private static final String WINDOW = "org.tinysep.amica.window";
    private static final String DOOR = "org.tinysep.amica.door";

    private Path list() {
        return tmp.resolve("state/drivers.xml");
    }

    private String listText() {
        try {
            return Files.readString(list());
        } catch (Exception e) {
            return "";
        }
    }

    /** @return the STATUS the file holds for {@code bsn}, or null when it has no such entry */
    private String fileStatus(String bsn) {
        Matcher m = Pattern.compile("<FULL_NAME>" + Pattern.quote(bsn) + "</FULL_NAME>\\s*<ENABLED>\\w+</ENABLED>\\s*"
                + "<STATUS>([^<]*)</STATUS>").matcher(listText());
        return m.find() ? m.group(1) : null;
    }

    @Test
    void listIsSeededInTheStateFolderAndDrivesTheApplications() throws Exception {
        StartReport report = dist.start();
        assertEquals(report.installed(), report.activeCount(), () -> String.join("\n", report.lines()));
        int apps = appCount();
        assertEquals(apps, report.active().get("5-apps"), "the banner reports the applications the list started");
        assertTrue(Files.isDirectory(tmp.resolve("state/felix-cache")));
        assertFalse(Files.exists(tmp.resolve("home/var")), "nothing written into the distribution folder");
        await(WAIT, () -> "ACTIVE".equals(fileStatus(WINDOW)), "STATUS ACTIVE for " + WINDOW + " in " + list());
        assertEquals(apps, listText().split("<DRIVER>", -1).length - 1);

        // disable: stopped at once, stays off across a restart (not even installed), enable brings it back
        String out = dist.shell("tinysep:drivers disable " + DOOR);
        assertTrue(out.contains("stopped " + DOOR), out);
        await(WAIT, () -> !dist.hasDriver("AmicaDoor"), "AmicaDoor driver gone");
        await(WAIT, () -> "DISABLED".equals(fileStatus(DOOR)), "STATUS DISABLED for " + DOOR);
        dist.restart();
        assertNull(dist.bundle(DOOR), "a disabled entry is not installed at start-up");
        assertTrue(dist.shell("tinysep:drivers").contains("DISABLED"));
        dist.shell("tinysep:drivers enable " + DOOR);
        await(WAIT, () -> dist.hasDriver("AmicaDoor"), "AmicaDoor driver back");
    }

    @Test
    void removedEntryIsUninstalledAndShellInstallSurvivesARestart() throws Exception {
        dist.start();
        await(WAIT, () -> fileStatus(WINDOW) != null, "the list on disk");
        long udpBefore = dist.bundle("org.tinysep.amica.busradio.udp").getBundleId();
        String windowJar = Pattern.compile("<FILE_PATH>([^<]*window[^<]*)</FILE_PATH>").matcher(listText()).results()
                .findFirst().orElseThrow().group(1);

        // remove the entry and reload: uninstalled, its driver gone, everything else untouched
        String without = listText().replaceAll("(?s)<DRIVER>\\s*<FILE_PATH>[^<]*window[^<]*</FILE_PATH>.*?</DRIVER>", "");
        Files.writeString(list(), without);
        String out = dist.shell("tinysep:drivers reload");
        assertTrue(out.contains("uninstalled " + WINDOW), out);
        assertEquals(List.of("uninstalled " + WINDOW + " (entry removed)"),
                out.lines().filter(l -> l.startsWith("  ")).map(String::strip).toList(),
                "nothing but the removed entry changes: " + out);
        assertNull(dist.bundle(WINDOW));
        assertFalse(dist.hasDriver("AmicaWindow"));
        assertEquals(Bundle.ACTIVE, dist.bundle("org.tinysep.amica.busradio.udp").getState());
        assertEquals(udpBefore, dist.bundle("org.tinysep.amica.busradio.udp").getBundleId());

        // the plain shell installs it from a folder of the user's: added to the list, so it survives a restart
        Path own = Files.createDirectories(tmp.resolve("my-bundles")).resolve("window.jar");
        Files.copy(tmp.resolve("home").resolve(windowJar), own);
        String installed = dist.shell("install " + own.toUri());
        Matcher id = Pattern.compile("Bundle ID: (\\d+)").matcher(installed);
        assertTrue(id.find(), installed);
        dist.shell("start " + id.group(1));
        await(WAIT, () -> dist.hasDriver("AmicaWindow"), "AmicaWindow driver after the shell install");
        await(WAIT, () -> "ACTIVE".equals(fileStatus(WINDOW)), "the shell-installed bundle in the list");
        assertTrue(listText().contains(own.toUri().toString()), listText());
        dist.restart();
        await(WAIT, () -> dist.hasDriver("AmicaWindow"), "AmicaWindow driver after the restart");
        assertEquals(own.toUri().toString(), dist.bundle(WINDOW).getLocation());

        // the plain shell uninstalls it: the entry goes too
        dist.shell("uninstall " + dist.bundle(WINDOW).getBundleId());
        await(WAIT, () -> fileStatus(WINDOW) == null, "the entry removed after the shell uninstall");
    }

    @Test
    void brokenListIsMovedAsideAndThePreviousOneStaysInForce() throws Exception {
        dist.start();
        await(WAIT, () -> "ACTIVE".equals(fileStatus(WINDOW)), "the list on disk");
        Files.writeString(list(), "<DRIVERS_LIST><DRIVER><FILE_PATH>x.jar</FILE_PATH>\n</DRIVERS_LIST>");
        TestDistribution.ShellFailure failure = assertThrows(TestDistribution.ShellFailure.class,
                () -> dist.shell("tinysep:drivers reload"));
        assertTrue(failure.getMessage().contains("drivers.xml: bad XML: line 2"), failure.getMessage());
        assertTrue(failure.getMessage().contains("moved aside to drivers.xml.broken-"), failure.getMessage());
        assertTrue(failure.getMessage().contains("kept the previous list"), failure.getMessage());
        try (Stream<Path> files = Files.list(tmp.resolve("state"))) {
            assertEquals(1, files.filter(f -> f.getFileName().toString().startsWith("drivers.xml.broken-")).count());
        }
        assertEquals("ACTIVE", fileStatus(WINDOW), "the previous list is written back");
        assertTrue(dist.hasDriver("AmicaWindow"), "nothing was stopped");

        // broken while the platform is down: moved aside at start-up, the list seeded again, every application up
        dist.stop();
        Files.writeString(list(), "not xml at all");
        StartReport report = dist.start();
        assertTrue(report.failures().isEmpty(), () -> String.join("\n", report.lines()));
        assertEquals(appCount(), report.active().get("5-apps"), () -> String.join("\n", report.lines()));
        try (Stream<Path> files = Files.list(tmp.resolve("state"))) {
            assertEquals(2, files.filter(f -> f.getFileName().toString().startsWith("drivers.xml.broken-")).count());
        }
        await(WAIT, () -> "ACTIVE".equals(fileStatus(WINDOW)), "a fresh list on disk");
    }

    private int appCount() throws java.io.IOException {
        return dist.apps().size();
    }
}
