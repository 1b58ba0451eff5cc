package org.tinysep.mqtt.board.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** CPU time and resident memory of a process, from /proc (Linux). */
record ProcStat(long pid, long cpuTicks, long rssKb) {

    static final double TICKS_PER_SECOND = 100.0; // USER_HZ on Linux

    static ProcStat of(long pid) {
        try {
            String stat = Files.readString(Path.of("/proc/" + pid + "/stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            long ticks = Long.parseLong(f[11]) + Long.parseLong(f[12]); // utime + stime (fields 14, 15)
            long rss = 0;
            for (String line : Files.readAllLines(Path.of("/proc/" + pid + "/status"))) {
                if (line.startsWith("VmRSS:")) {
                    rss = Long.parseLong(line.replaceAll("[^0-9]", ""));
                }
            }
            return new ProcStat(pid, ticks, rss);
        } catch (IOException | RuntimeException e) {
            return new ProcStat(pid, 0, 0);
        }
    }

    /** @return percent of one core used between {@code before} and this sample, over {@code seconds} */
    double cpuPercentSince(ProcStat before, double seconds) {
        return (cpuTicks - before.cpuTicks) / TICKS_PER_SECOND / seconds * 100.0;
    }
}
