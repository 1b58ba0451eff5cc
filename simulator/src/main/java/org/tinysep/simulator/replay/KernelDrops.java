package org.tinysep.simulator.replay;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The Linux kernel's count of datagrams dropped at a full UDP socket buffer, for measurements of replays and
 * benchmarks (issue 14). Java opens UDP sockets dual-stack, so a socket bound to 127.0.0.1 is listed in
 * {@code /proc/net/udp6} as {@code ::ffff:127.0.0.1} ({@code 0000000000000000FFFF00000100007F}); an IPv4-only socket
 * is in {@code /proc/net/udp}. Both files are read.
 */
public final class KernelDrops {

    static final List<Path> FILES = List.of(Path.of("/proc/net/udp"), Path.of("/proc/net/udp6"));

    private KernelDrops() {
    }

    /**
     * @param port a UDP port bound on 127.0.0.1 (IPv4 or dual-stack)
     * @return the drops of the sockets bound to 127.0.0.1:{@code port} (last column of the tables), or -1 where
     *         neither file can be read (not Linux)
     */
    public static long at127(int port) {
        return of(FILES, port);
    }

    static long of(List<Path> files, int port) {
        String hexPort = String.format(Locale.ROOT, ":%04X", port);
        List<String> locals = List.of("0100007F" + hexPort, "0000000000000000FFFF00000100007F" + hexPort);
        long sum = 0;
        boolean read = false;
        for (Path f : files) {
            if (!Files.isReadable(f)) {
                continue;
            }
            try {
                for (String line : Files.readAllLines(f)) {
                    String[] cols = line.trim().split("\\s+");
                    if (cols.length > 2 && locals.contains(cols[1].toUpperCase(Locale.ROOT))) {
                        sum += Long.parseLong(cols[cols.length - 1]);
                    }
                }
                read = true;
            } catch (IOException | NumberFormatException e) {
                // unreadable table: as if absent
            }
        }
        return read ? sum : -1;
    }
}
