package org.tinysep.runtime.internal.shell;

import java.time.Clock;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.tinysep.api.log.LogQuery;
import org.tinysep.runtime.internal.directory.DeviceOrigins;
import org.tinysep.runtime.internal.directory.Inventory;

/**
 * Parses the arguments of {@code events} and {@code packets} into a {@link LogQuery}:
 * {@code [N] [--from T] [--to T] [--device D] [--kind K[,K]] [--limit N]} (options in any order; {@code --device}
 * and {@code --kind} may repeat). A device is a current device's UID, unique UID prefix or name, a driver's UID
 * or name, or any origin text as written in the log (a device removed since). A current device with a node
 * address also matches the packets of its node ({@code node <address>}).
 */
final class HistoryArguments {

    static final String USAGE = "[N] [--from T] [--to T] [--device D] [--kind K] [--limit N]";
    private static final Set<String> OPTIONS = Set.of("--from", "--to", "--device", "--kind", "--limit");

    private HistoryArguments() {
    }

    /**
     * @param kinds the accepted kind names (upper case)
     * @throws IllegalArgumentException on an unknown option, a missing value or a bad time, number or kind
     */
    static LogQuery parse(String[] args, Set<String> kinds, Inventory inventory, Clock clock, int defaultLimit) {
        Instant now = clock.instant();
        Instant from = null;
        Instant to = null;
        Set<String> origins = new LinkedHashSet<>();
        Set<String> wanted = new LinkedHashSet<>();
        int limit = defaultLimit;
        List<String> a = args == null ? List.of() : List.of(args);
        for (int i = 0; i < a.size(); i++) {
            String opt = a.get(i);
            if (opt.matches("\\d+") && i == 0) {
                limit = number(opt);
                continue;
            }
            if (!opt.startsWith("--")) {
                throw new IllegalArgumentException("unexpected '" + opt + "'; usage: " + USAGE);
            }
            if (!OPTIONS.contains(opt)) {
                throw new IllegalArgumentException("unknown option " + opt + "; usage: " + USAGE);
            }
            if (i + 1 >= a.size()) {
                throw new IllegalArgumentException(opt + " needs a value; usage: " + USAGE);
            }
            String value = a.get(++i);
            switch (opt) {
                case "--from" -> from = TimeArgument.parse(value, now, clock.getZone());
                case "--to" -> to = TimeArgument.parse(value, now, clock.getZone());
                case "--device" -> origins.addAll(DeviceOrigins.of(value, inventory));
                case "--kind" -> wanted.addAll(kinds(value, kinds));
                case "--limit" -> limit = number(value);
                default -> throw new IllegalArgumentException("unknown option " + opt + "; usage: " + USAGE);
            }
        }
        return new LogQuery(from, to, origins, wanted, limit);
    }

    private static int number(String s) {
        try {
            int n = Integer.parseInt(s.strip());
            if (n >= 1) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException("the number of lines must be a whole number of at least 1, not '" + s + "'");
    }

    private static List<String> kinds(String value, Set<String> accepted) {
        List<String> out = new ArrayList<>();
        for (String k : value.split(",")) {
            String n = k.strip().toUpperCase(Locale.ROOT);
            if (!accepted.contains(n)) {
                throw new IllegalArgumentException("unknown kind '" + k.strip() + "' (kinds: "
                        + String.join(", ", accepted) + ")");
            }
            out.add(n);
        }
        return out;
    }
}
