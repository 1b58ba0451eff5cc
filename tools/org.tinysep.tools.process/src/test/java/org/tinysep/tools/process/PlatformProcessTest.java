package org.tinysep.tools.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The helper against real child processes: a bash script stands in for {@code java}, printing what the launcher
 * prints (a log line, the banner) and answering like its shell, so every path (up, late, ended, hung) runs for real.
 */
class PlatformProcessTest {

    static final String BANNER = "TinySEP 0.1.0-SNAPSHOT up in 1.3 s (interactive, start level 6): 40/41 bundles"
            + " active [1-core 12, 5-apps 28] — 1 FAILED, see below";
    /** A shell: "echo x" prints x, anything else is echoed back with the prompt; ends with its input. */
    static final String SHELL = "while read -r line; do case \"$line\" in echo\\ *) echo \"${line#echo }\";;"
            + " *) echo \"g! answer to $line\";; esac; done\n";

    @TempDir
    Path home;

    @Test
    void startsWaitsForBannerAndShellThenStopsInOrder() throws Exception {
        PlatformLaunch launch = fake("echo \"args=$*\"\necho \"heap=$TINYSEP_HEAP\"\necho 'starting' >&2\n"
                + "echo '" + BANNER + "'\n" + SHELL + "echo 'bye' >&2\nexit 0\n")
                .jvm(List.of("-Xmx64m", "TINYSEP_HEAP=small")).args("--var", "state")
                .cfg("org.tinysep.amica.busradio.udp", "port=4711\n");
        try (PlatformProcess p = launch.start(Duration.ofSeconds(20))) {
            assertEquals("40/41 1 interactive", p.banner().active() + "/" + p.banner().installed() + " "
                    + p.banner().failed() + " " + p.banner().mode());
            assertTrue(p.msToBanner() > 0 && p.msToBanner() <= p.msSinceStart(), "ms to banner " + p.msToBanner());
            assertEquals(List.of("answer to tinysep:devices"), p.command("tinysep:devices"));
            assertTrue(p.lastLines().contains("args=-Xmx64m -jar tinysep.jar --var state"), p.lastLines().toString());
            assertTrue(p.lastLines().contains("heap=small"), p.lastLines().toString());
            assertEquals("port=4711\n", Files.readString(home.resolve("etc/org.tinysep.amica.busradio.udp.cfg")));
            assertEquals(0, p.stop(Duration.ofSeconds(10)));
            assertTrue(Files.readString(p.log()).contains("bye"), "it ended on its own, after its input");
        }
    }

    @Test
    void noBannerInTimeIsAClearErrorWithTheLastLinesAndTheChildIsGone() throws Exception {
        PlatformLaunch launch = fake("echo 'Felix starting'\necho 'ERROR bundle 7 would not resolve' >&2\nsleep 60\n");
        IOException e = assertThrows(IOException.class, () -> launch.start(Duration.ofSeconds(2)));
        assertTrue(e.getMessage().contains("did not print its banner within 2 s"), e.getMessage());
        assertTrue(e.getMessage().contains("| Felix starting"), e.getMessage());
        assertTrue(e.getMessage().contains("| ERROR bundle 7 would not resolve"), e.getMessage());
        assertEquals(0, ChildProcesses.running(), "the child was killed and reaped");
    }

    @Test
    void anEndBeforeTheBannerSaysSoAtOnce() throws Exception {
        long t0 = System.nanoTime();
        IOException e = assertThrows(IOException.class,
                () -> fake("echo 'no such option' >&2\nexit 3\n").start(Duration.ofSeconds(60)));
        assertTrue(e.getMessage().contains("ended before its banner (exit value 3)"), e.getMessage());
        assertTrue(e.getMessage().contains("| no such option"), e.getMessage());
        assertTrue(System.nanoTime() - t0 < 30_000_000_000L, "without waiting out the timeout");
    }

    @Test
    void aChildThatIgnoresTheEndOfItsInputIsKilled() throws Exception {
        PlatformProcess p = fake("echo '" + BANNER + "'\n" + SHELL + "sleep 60\n").start(Duration.ofSeconds(20));
        IllegalStateException late = assertThrows(IllegalStateException.class, () -> p.stop(Duration.ofSeconds(1)));
        assertTrue(late.getMessage().contains("did not stop within 1 s; killed"), late.getMessage());
        assertFalse(p.alive());
    }

    @Test
    void aDaemonIsStoppedBySigterm() throws Exception {
        PlatformLaunch launch = fake("trap 'echo stopped-by-term >&2; exit 0' TERM\necho '"
                + BANNER.replace("interactive", "daemon") + "'\nwhile true; do sleep 0.1; done\n")
                .daemon().stdoutCopy(home.resolve("platform.out"));
        PlatformProcess p = launch.start(Duration.ofSeconds(20));
        assertEquals("daemon", p.banner().mode());
        assertEquals(0, p.stop(Duration.ofSeconds(20)));
        assertTrue(Files.readString(p.log()).contains("stopped-by-term"));
        assertTrue(Files.readString(home.resolve("platform.out")).contains("bundles active"));
        assertTrue(launch.command().contains("--daemon"));
    }

    @Test
    void awaitUntilFailsWhenTheChildEnds() throws Exception {
        PlatformProcess p = fake("echo '" + BANNER.replace("interactive", "daemon") + "'\nsleep 1\n")
                .daemon().start(Duration.ofSeconds(20));
        IOException e = assertThrows(IOException.class,
                () -> p.awaitUntil(() -> false, "the radio bound", Duration.ofSeconds(30)));
        assertTrue(e.getMessage().contains("ended before the radio bound"), e.getMessage());
    }

    /** @return a launch whose "java" is a bash script with {@code body} */
    private PlatformLaunch fake(String body) throws IOException {
        Path script = home.resolve("fake-java.sh");
        Files.writeString(script, "#!/bin/bash\n" + body);
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwx------"));
        return PlatformProcess.in(home).java(script.toString());
    }
}
