package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The shipped systemd unit: restart on failure, a watchdog fed through sd_notify, options the launcher takes. */
class SystemdUnitTest {

    private static final Path UNIT = Path.of("src/main/dist/systemd/tinysep.service");

    @Test
    void theUnitRestartsOnFailureAndHasAWatchdogTheLauncherFeeds() throws Exception {
        List<String> lines = Files.readAllLines(UNIT).stream().map(String::strip)
                .filter(l -> !l.startsWith("#")).toList();
        for (String wanted : List.of("Type=notify", "NotifyAccess=all", "Restart=on-failure", "WatchdogSec=90",
                "StartLimitIntervalSec=0")) {
            assertTrue(lines.contains(wanted), wanted);
        }
        String exec = lines.stream().filter(l -> l.startsWith("ExecStart=")).findFirst().orElseThrow();
        List<String> args = Arrays.asList(exec.split(" "));
        Options options = Options.parse(args.subList(args.indexOf("-jar") + 2, args.size()), Map.of(), Path.of("."));
        assertTrue(options.daemon(), "no interactive shell under systemd");
        assertEquals(Path.of("/var/lib/tinysep"), options.var());
    }

    @Test
    void systemdWaitsLongerThanTheLauncherWaitsForTheFrameworkToStop() throws Exception {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?m)^TimeoutStopSec=(\\d+)$")
                .matcher(Files.readString(UNIT));
        assertTrue(m.find(), "TimeoutStopSec set");
        long systemd = Long.parseLong(m.group(1));
        assertTrue(systemd >= Main.STOP_TIMEOUT.toSeconds() + 10, "systemd " + systemd + " s, launcher "
                + Main.STOP_TIMEOUT.toSeconds() + " s: a slow stop (backups being saved) is not killed mid-way");
        assertTrue(Main.STOP_TIMEOUT.toSeconds() >= 25 + 30, "the backup store's 25 s after the drivers' stop");
    }

    @Test
    void systemdAcceptsTheUnit() throws Exception {
        if (!Files.isExecutable(Path.of("/usr/bin/systemd-analyze"))) {
            return;
        }
        Process p = new ProcessBuilder("systemd-analyze", "verify", UNIT.toAbsolutePath().toString())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes());
        assertEquals(0, p.waitFor(), out);
        assertTrue(out.isBlank(), out);
    }
}
