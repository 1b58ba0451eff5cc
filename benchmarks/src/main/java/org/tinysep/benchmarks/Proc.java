package org.tinysep.benchmarks;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** What Linux says about a process: resident size, CPU time, and (through jcmd) its live heap after a full GC. */
final class Proc {

    /** clock ticks per second of /proc/<pid>/stat (USER_HZ; 100 on every Linux we run on) */
    static final long HZ = 100;
    private static final Pattern USED = Pattern.compile("used (\\d+)K");

    private Proc() {
    }

    /** @return VmRSS in KiB, or -1 */
    static long rssKb(long pid) {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/" + pid + "/status"))) {
                if (line.startsWith("VmRSS:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", ""));
                }
            }
        } catch (IOException | RuntimeException e) {
            // gone
        }
        return -1;
    }

    /** @return user + system CPU time in ticks (1/100 s), or -1 */
    static long cpuTicks(long pid) {
        try {
            String stat = Files.readString(Path.of("/proc/" + pid + "/stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return Long.parseLong(f[11]) + Long.parseLong(f[12]); // fields 14 and 15 of stat
        } catch (IOException | RuntimeException e) {
            return -1;
        }
    }

    /** @return the heap in use right after a full GC (jcmd GC.run, GC.heap_info), in KiB; -1 if jcmd fails */
    static long liveHeapKb(long pid) {
        run("jcmd", Long.toString(pid), "GC.run");
        long used = 0;
        boolean any = false;
        for (String line : run("jcmd", Long.toString(pid), "GC.heap_info")) {
            String l = line.strip();
            if (l.startsWith("Metaspace") || l.startsWith("class space")) {
                continue;
            }
            if (l.contains(" total ") && (l.contains("generation") || l.contains("heap") || l.startsWith("garbage-first"))) {
                Matcher m = USED.matcher(l);
                if (m.find()) {
                    used += Long.parseLong(m.group(1));
                    any = true;
                }
            }
        }
        return any ? used : -1;
    }

    /** Runs a command (bounded: 60 s) and returns its output lines; empty when it fails. */
    static List<String> run(String... command) {
        List<String> out = new ArrayList<>();
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            out.addAll(new String(p.getInputStream().readAllBytes()).lines().toList());
            if (!p.waitFor(60, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        } catch (IOException e) {
            out.add("(" + e.getMessage() + ")");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return out;
    }

    /** CPU use of a process over a wall-time window, as % of one core. */
    record CpuWindow(long pid, long ticks, long nanos) {
        static CpuWindow start(long pid) {
            return new CpuWindow(pid, cpuTicks(pid), System.nanoTime());
        }

        double percentOfOneCore() {
            double cpuSeconds = (cpuTicks(pid) - ticks) / (double) HZ;
            double wall = (System.nanoTime() - nanos) / 1e9;
            return 100.0 * cpuSeconds / wall;
        }
    }
}
