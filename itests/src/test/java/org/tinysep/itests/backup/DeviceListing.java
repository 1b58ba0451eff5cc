package org.tinysep.itests.backup;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;

/**
 * {@code tinysep:devices} output reduced to what a restart must keep (docs/backup.md): per device its header
 * without the status, what it provides, its connections, its node line and the parameters that are settings or
 * kept state; live readings (packet counters, keep-alive readings, the route) are dropped. Blocks are keyed by
 * device UID and their lines sorted, since registration order is not defined.
 */
final class DeviceListing {

    static final Set<String> KEPT = Set.of("name", "room", "kind", "location", "position", "deadbandCelsius",
            "mode", "node", "nodeTypes", "lastSeen", "lastActivityPerRoom");

    private DeviceListing() {
    }

    static TreeMap<String, List<String>> of(List<String> lines) {
        TreeMap<String, List<String>> blocks = new TreeMap<>();
        List<String> current = null;
        for (String line : lines) {
            if (!line.startsWith("  ")) {
                String uid = line.split(" ", 2)[0];
                current = new ArrayList<>();
                current.add(line.replaceAll(" \\[[^\\]]*\\] driver=", " driver="));
                blocks.put(uid, current);
            } else if (current != null) {
                current.add(line.startsWith("  parameters: ") ? "  parameters: " + kept(line.substring(14))
                        : line);
            }
        }
        blocks.values().forEach(b -> b.subList(1, b.size()).sort(null));
        return blocks;
    }

    /** @return the kept {@code key=value} pairs; values may contain ", " so keys are found by the known names */
    static String kept(String parameters) {
        List<String> out = new ArrayList<>();
        for (String part : parameters.split(", (?=[A-Za-z]+=)")) {
            int eq = part.indexOf('=');
            if (eq > 0 && KEPT.contains(part.substring(0, eq))) {
                out.add(part);
            }
        }
        return String.join(", ", out);
    }

    static String render(TreeMap<String, List<String>> blocks) {
        StringBuilder sb = new StringBuilder();
        blocks.values().forEach(b -> b.forEach(l -> sb.append(l).append('\n')));
        return sb.toString();
    }
}
