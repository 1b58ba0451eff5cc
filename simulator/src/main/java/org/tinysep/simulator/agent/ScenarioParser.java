package org.tinysep.simulator.agent;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Parses a scenario timeline, one step a line, {@code #} starts a comment:
 * <pre>
 * 07:10 anna bedroom -> bathroom      07:30 anna kitchen        08:30 anna leaves
 * 12:00 anna arrives [in kitchen]     14:02 anna collapses [in bathroom]
 * 22:30 anna sleeps [in bedroom]      06:45 anna wakes           09:00 rex (pet) living room
 * 10:00 battery hall-motion off       10:20 battery hall-motion on
 * </pre>
 * Times are {@code H:MM} or {@code H:MM:SS} of the simulated day. Every error names the source and line.
 */
public final class ScenarioParser {

    private static final Pattern LINE = Pattern.compile(
            "(\\d{1,2}):(\\d{2})(?::(\\d{2}))?\\s+([A-Za-z][A-Za-z0-9_-]*)(\\s+\\(pet\\))?(?:\\s+(.*))?");

    private final Function<String, Optional<String>> rooms;
    private final Set<String> nodeIds;

    /** @param rooms resolves a room name (case-insensitive) to the flat's exact name */
    public ScenarioParser(Function<String, Optional<String>> rooms, Set<String> nodeIds) {
        this.rooms = rooms;
        this.nodeIds = nodeIds;
    }

    public Scenario parse(String text, String source) {
        List<Step> steps = new ArrayList<>();
        Set<String> pets = new HashSet<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].replaceFirst("#.*", "").trim();
            if (line.isEmpty()) {
                continue;
            }
            try {
                steps.add(parseLine(i + 1, line, pets));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": " + e.getMessage() + " in '" + line + "'", e);
            }
        }
        return new Scenario(steps, pets);
    }

    private Step parseLine(int n, String line, Set<String> pets) {
        Matcher m = LINE.matcher(line);
        if (!m.matches()) {
            throw new IllegalArgumentException("expected 'HH:MM[:SS] <name> [(pet)] <what>'");
        }
        int h = Integer.parseInt(m.group(1));
        int min = Integer.parseInt(m.group(2));
        int s = m.group(3) == null ? 0 : Integer.parseInt(m.group(3));
        if (h > 23 || min > 59 || s > 59) {
            throw new IllegalArgumentException("bad time " + line.split("\\s")[0]);
        }
        int at = h * 3600 + min * 60 + s;
        String name = m.group(4).toLowerCase(Locale.ROOT);
        String rest = m.group(6) == null ? "" : m.group(6).trim().replaceAll("\\s+", " ");
        if (name.equals("battery")) {
            return battery(n, at, rest);
        }
        if (m.group(5) != null) {
            pets.add(name);
        }
        String what = rest.toLowerCase(Locale.ROOT);
        if (what.isEmpty()) {
            throw new IllegalArgumentException("nothing happens to " + name);
        }
        if (what.contains("->")) {
            String[] r = rest.split("->", -1);
            if (r.length != 2) {
                throw new IllegalArgumentException("expected '<room> -> <room>'");
            }
            return new Step(n, at, name, Action.FROM_TO, room(r[0]), room(r[1]), null, true);
        }
        String[] w = what.split(" ", 2);
        Action a = switch (w[0]) {
        case "leaves" -> Action.LEAVES;
        case "arrives" -> Action.ARRIVES;
        case "collapses" -> Action.COLLAPSES;
        case "sleeps" -> Action.SLEEPS;
        case "wakes" -> Action.WAKES;
        default -> what.equals("gets up") ? Action.WAKES : Action.GO;
        };
        if (a == Action.GO) {
            return new Step(n, at, name, a, room(rest), null, null, true);
        }
        if (a == Action.WAKES || a == Action.LEAVES) {
            if (w.length > 1 && a == Action.LEAVES || a == Action.WAKES && !(w.length == 1 || what.equals("gets up"))) {
                throw new IllegalArgumentException("'" + w[0] + "' takes no room");
            }
            return new Step(n, at, name, a, null, null, null, true);
        }
        String room = null;
        if (w.length > 1) {
            if (!w[1].startsWith("in ")) {
                throw new IllegalArgumentException("expected '" + w[0] + " in <room>'");
            }
            room = room(rest.substring(w[0].length() + 4));
        }
        return new Step(n, at, name, a, room, null, null, true);
    }

    private Step battery(int n, int at, String rest) {
        String[] w = rest.split(" ");
        if (w.length != 2 || !(w[1].equalsIgnoreCase("on") || w[1].equalsIgnoreCase("off"))) {
            throw new IllegalArgumentException("expected 'battery <node id> on|off'");
        }
        if (!nodeIds.contains(w[0])) {
            throw new IllegalArgumentException("unknown node '" + w[0] + "'");
        }
        return new Step(n, at, null, Action.BATTERY, null, null, w[0], w[1].equalsIgnoreCase("on"));
    }

    private String room(String name) {
        return rooms.apply(name.trim()).orElseThrow(() -> new IllegalArgumentException("unknown room '" + name.trim() + "'"));
    }
}
