package org.tinysep.benchmarks;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.tools.process.Ports;

/**
 * What every benchmark shares: the distribution, a scratch folder, smoke or full, the JVM options compared
 * (the JVM's defaults and the distribution's chosen {@code etc/jvm.options}), the report and the plots' folder.
 */
record Bench(Path dist, Path work, boolean smoke, List<String> chosen, Report report, Path images) {

    static final List<String> DEFAULTS = List.of();

    /** @return the options in the distribution's {@code etc/jvm.options} (one or more a line, # comments) */
    static List<String> chosenOptions(Path dist) throws IOException {
        List<String> out = new ArrayList<>();
        Path f = dist.resolve("etc/jvm.options");
        if (Files.isRegularFile(f)) {
            for (String line : Files.readAllLines(f)) {
                String l = line.strip();
                if (!l.isEmpty() && !l.startsWith("#")) {
                    out.addAll(List.of(l.split("\\s+")));
                }
            }
        }
        return out;
    }

    /** A fresh copy of the distribution with its AmICA radio on a free port. */
    Installed install(String name) throws IOException {
        Path home = work.resolve(name + "/home");
        Path var = work.resolve(name + "/var");
        Files.createDirectories(var);
        int port = Ports.freeUdp();
        int syncPort = Ports.freeUdp();
        MeasuredPlatform.install(dist, home, port, syncPort);
        return new Installed(home, var, port, syncPort);
    }

    record Installed(Path home, Path var, int amicaPort, int syncPort) {
        MeasuredPlatform start(List<String> options) throws IOException {
            return MeasuredPlatform.start(home, var, amicaPort, options);
        }
    }

    /** @return devices per driver name, from {@code tinysep:drivers} */
    static java.util.Map<String, Integer> devicesPerDriver(MeasuredPlatform p) {
        java.util.Map<String, Integer> out = new java.util.TreeMap<>();
        for (String line : p.command("tinysep:drivers", Duration.ofSeconds(120))) {
            String[] cells = line.split("\\|");
            if (cells.length >= 4) {
                try {
                    out.merge(cells[0].strip(), Integer.parseInt(cells[2].strip()), Integer::sum);
                } catch (NumberFormatException notARow) {
                    // header or another table
                }
            }
        }
        return out;
    }

    /** Waits (bounded) until the drivers hold at least {@code count} devices of driver {@code name}; @return ms waited */
    static double awaitDevices(MeasuredPlatform p, String name, int count, Duration timeout) throws InterruptedException {
        long t0 = System.nanoTime();
        long deadline = t0 + timeout.toNanos();
        while (devicesPerDriver(p).getOrDefault(name, 0) < count) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException(name + ": fewer than " + count + " devices after " + timeout
                        + ": " + devicesPerDriver(p));
            }
            Thread.sleep(200);
        }
        return (System.nanoTime() - t0) / 1e6;
    }

    /** The AmICA UDP radio's own counters ({@code tinysep:drivers}): datagrams received and rejected. */
    record RadioCounters(long received, long rejected) {
    }

    static RadioCounters radio(MeasuredPlatform p) {
        for (String line : p.command("tinysep:drivers", Duration.ofSeconds(120))) {
            if (line.startsWith("BusRadioAmicaUdp ")) {
                // a payload the radio's ordered queue had to drop (delivery.dropped) is lost like a rejected one
                return new RadioCounters(counter(line, "received"),
                        counter(line, "rejected") + Math.max(0, counter(line, "delivery.dropped")));
            }
        }
        throw new IllegalStateException("no BusRadioAmicaUdp in tinysep:drivers");
    }

    private static long counter(String line, String key) {
        Matcher m = Pattern.compile("[ ,]" + key + "=(\\d+)").matcher(line);
        return m.find() ? Long.parseLong(m.group(1)) : -1;
    }

    static void sleep(double seconds) throws InterruptedException {
        Thread.sleep((long) (seconds * 1000));
    }
}
