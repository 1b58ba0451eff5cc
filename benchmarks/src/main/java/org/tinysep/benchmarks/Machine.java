package org.tinysep.benchmarks;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Facts about the machine a run measured on: cores, memory, JVM, load. */
final class Machine {

    private Machine() {
    }

    static int cores() {
        return Runtime.getRuntime().availableProcessors();
    }

    /** @return the first line of a /proc file, or "?" */
    static String firstLine(String file, String prefix) {
        try {
            return Files.readAllLines(Path.of(file)).stream().filter(l -> l.startsWith(prefix)).findFirst()
                    .map(String::strip).orElse("?");
        } catch (IOException e) {
            return "?";
        }
    }

    static String memory() {
        return firstLine("/proc/meminfo", "MemTotal:").replaceAll("\\s+", " ");
    }

    static String cpuModel() {
        String l = firstLine("/proc/cpuinfo", "model name");
        return l.contains(":") ? l.substring(l.indexOf(':') + 1).strip() : l;
    }

    /** @return the 1, 5 and 15 minute load averages */
    static String load() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (IOException e) {
            return "?";
        }
    }

    static String jvm() {
        return System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version");
    }

    static String java() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }
}
