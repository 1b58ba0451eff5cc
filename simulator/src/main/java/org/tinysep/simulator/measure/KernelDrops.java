package org.tinysep.simulator.measure;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The Linux kernel's count of datagrams it dropped at a UDP socket because its receive buffer was full (last column
 * of {@code /proc/net/udp} and {@code /proc/net/udp6}). Both tables are read: the JVM opens its sockets dual-stack
 * ({@code [::ffff:127.0.0.1]}), so the radios' sockets are listed in {@code udp6}, and a reader of {@code udp} alone
 * always saw 0. Used by the replay test and the benchmarks.
 */
public final class KernelDrops {

    /** The tables read, IPv4 and IPv6. */
    public static final List<Path> TABLES = List.of(Path.of("/proc/net/udp"), Path.of("/proc/net/udp6"));

    private KernelDrops() {
    }

    /**
     * @return the drops at every UDP socket whose local port is {@code port} (any local address, both tables), or
     *         -1 where neither table can be read (not Linux)
     */
    public static long at(int port) {
        return at(port, TABLES);
    }

    static long at(int port, List<Path> tables) {
        long sum = 0;
        boolean read = false;
        for (Path table : tables) {
            if (!Files.isReadable(table)) {
                continue;
            }
            try {
                sum += drops(Files.readAllLines(table), port);
                read = true;
            } catch (IOException | RuntimeException e) {
                // a table that cannot be read or parsed counts as absent
            }
        }
        return read ? sum : -1;
    }

    /** @return the drops of the lines of one table whose local address has port {@code port} */
    static long drops(List<String> lines, int port) {
        String suffix = String.format(":%04X", port);
        long sum = 0;
        for (String line : lines) {
            String[] f = line.trim().split("\\s+");
            // sl local_address rem_address st tx_queue:rx_queue tr:tm->when retrnsmt uid timeout inode ref pointer drops
            if (f.length >= 13 && f[0].endsWith(":") && f[1].endsWith(suffix)) {
                sum += Long.parseLong(f[f.length - 1]);
            }
        }
        return sum;
    }
}
