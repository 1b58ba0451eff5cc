package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The distribution's JVM options as {@code bin/tinysep} gives them to the JVM (the script itself, reading
 * {@code etc/jvm.options}): the JVM accepts every one, and the memory levers of issue 29 are in effect
 * (docs/footprint.md, "Session 33").
 */
class JvmOptionsTest {

    private static final Path DIST = Path.of("src/main/dist");
    private static final Pattern FLAG = Pattern.compile("(?m)^\\s*\\S+\\s+(\\w+)\\s+= (\\S+)\\s+\\{[^}]*\\}\\s+\\{(\\w+)");

    /** @return the JVM's final flags (name to value, set on the command line) when bin/tinysep starts it */
    private static Map<String, String> flagsSetByTheScript(Path home) throws IOException, InterruptedException {
        // a home with the shipped script and options and a stand-in tinysep.jar (java opens the jar before -version)
        Files.createDirectories(home.resolve("bin"));
        Files.createDirectories(home.resolve("etc"));
        Files.copy(DIST.resolve("bin/tinysep"), home.resolve("bin/tinysep"));
        Files.copy(DIST.resolve("etc/jvm.options"), home.resolve("etc/jvm.options"));
        Manifest mf = new Manifest();
        mf.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        mf.getMainAttributes().put(Attributes.Name.MAIN_CLASS, "org.tinysep.launcher.Main");
        try (JarOutputStream jar = new JarOutputStream(Files.newOutputStream(home.resolve("tinysep.jar")), mf)) {
            jar.flush();
        }
        ProcessBuilder pb = new ProcessBuilder("bash", home.resolve("bin/tinysep").toString()).redirectErrorStream(true);
        // java -version ends the JVM after the options are read, before the jar's main class runs
        pb.environment().put("JAVA_OPTS", "-XX:+PrintFlagsFinal -version");
        pb.environment().remove("TINYSEP_JVM_OPTIONS");
        pb.environment().put("PATH", Path.of(System.getProperty("java.home"), "bin") + ":"
                + System.getenv().getOrDefault("PATH", "/usr/bin:/bin"));
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the JVM did not end");
        assertEquals(0, p.exitValue(), "the JVM refused etc/jvm.options:\n" + out);
        Map<String, String> set = new HashMap<>();
        Matcher m = FLAG.matcher(out);
        while (m.find()) {
            if (m.group(3).equals("command")) {
                set.put(m.group(1), m.group(2));
            }
        }
        return set;
    }

    @Test
    void theJvmTakesEveryOptionAndTrimsItsNativeHeap(@TempDir Path home) throws Exception {
        Map<String, String> set = flagsSetByTheScript(home);
        // C1 only, serial GC, small heap (issue 14): kept
        for (String flag : List.of("TieredStopAtLevel", "UseSerialGC", "MaxHeapFreeRatio", "ThreadStackSize")) {
            assertTrue(set.containsKey(flag), flag + " not set by etc/jvm.options: " + set.keySet());
        }
        assertEquals("1", set.get("TieredStopAtLevel"));
        // session 33: malloc's freed memory goes back to the system (about 2.5 MB idle)
        long trim = Long.parseLong(set.getOrDefault("TrimNativeHeapInterval", "0"));
        assertTrue(trim > 0 && trim <= 60_000, "the native heap is trimmed periodically: TrimNativeHeapInterval=" + trim);
        // session 33: C1 compiles later (once-used start code stays interpreted: a smaller code cache)
        double scaling = Double.parseDouble(set.getOrDefault("CompileThresholdScaling", "1.0"));
        assertTrue(scaling > 1.0, "C1 compiles later than the JDK's default: CompileThresholdScaling=" + scaling);
        // session 34: no perf-data sampling (the watcher thread's 20 wake-ups a second at idle)
        assertEquals("false", set.get("UsePerfData"), "perf data is off: UsePerfData=" + set.get("UsePerfData"));
        // session 36: a young generation of a fifth of the heap, not a third (about 2.5 MB less idle)
        int newRatio = Integer.parseInt(set.getOrDefault("NewRatio", "2"));
        assertTrue(newRatio >= 4, "the young generation is at most a fifth of the heap: NewRatio=" + newRatio);
    }
}
