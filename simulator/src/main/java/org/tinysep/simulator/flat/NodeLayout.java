package org.tinysep.simulator.flat;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Parses a node layout file: one node a line, five or six fields separated by {@code |}:
 * {@code id | family | address | types | room | options}. Types are comma-separated node type names; options are
 * space-separated {@code key=value} pairs. {@code #} starts a comment. Every error names the source and line.
 */
public final class NodeLayout {

    private NodeLayout() {
    }

    public static List<NodeSpec> parse(String text, String source, House house) {
        List<NodeSpec> nodes = new ArrayList<>();
        Set<String> ids = new HashSet<>();
        Set<String> addresses = new HashSet<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].replaceFirst("#.*", "").trim();
            if (line.isEmpty()) {
                continue;
            }
            String where = source + ":" + (i + 1) + ": ";
            try {
                NodeSpec n = parseLine(line, house);
                if (!ids.add(n.id())) {
                    throw new IllegalArgumentException("duplicate node id '" + n.id() + "'");
                }
                if (!addresses.add(n.family() + " " + n.address())) {
                    throw new IllegalArgumentException("duplicate address " + n.address());
                }
                nodes.add(n);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(where + e.getMessage() + " in '" + lines[i].trim() + "'", e);
            }
        }
        return nodes;
    }

    private static NodeSpec parseLine(String line, House house) {
        String[] f = line.split("\\|", -1);
        if (f.length < 5 || f.length > 6) {
            throw new IllegalArgumentException("expected 'id | family | address | types | room [| options]'");
        }
        String id = f[0].trim();
        if (!id.matches("[A-Za-z0-9._-]+")) {
            throw new IllegalArgumentException("bad node id '" + id + "' (letters, digits, . _ -)");
        }
        Family family = Family.parse(f[1]);
        if (family == null) {
            throw new IllegalArgumentException("unknown family '" + f[1].trim() + "' (AmICA or SunSPOT)");
        }
        String address = address(family, f[2].trim());
        List<String> types = new ArrayList<>();
        for (String t : f[3].split(",")) {
            String type = t.trim().toLowerCase(Locale.ROOT);
            boolean known = family == Family.AMICA ? AmicaNodeType.fromTypeName(type).isPresent()
                    : SunSpotSensorType.fromTypeName(type).isPresent();
            if (!known) {
                throw new IllegalArgumentException("unknown " + family + " node type '" + type + "'");
            }
            types.add(type);
        }
        String room = house.roomName(f[4].trim())
                .orElseThrow(() -> new IllegalArgumentException("unknown room '" + f[4].trim() + "'"));
        Map<String, String> options = new LinkedHashMap<>();
        if (f.length == 6) {
            for (String o : f[5].trim().split("\\s+")) {
                if (o.isEmpty()) {
                    continue;
                }
                String[] kv = o.split("=", 2);
                if (kv.length != 2 || !Set.of("door", "agent", "percent", "person").contains(kv[0])) {
                    throw new IllegalArgumentException("bad option '" + o + "' (door=outer|inner, agent=<pet or "
                            + "wearer>, percent=<0..100>, person=<wearer's name for the platform>)");
                }
                options.put(kv[0], kv[1]);
            }
        }
        check(options, types);
        return new NodeSpec(id, family, address, types, room, options);
    }

    private static String address(Family family, String text) {
        if (family == Family.AMICA) {
            AmicaAddress a = AmicaAddress.parse(text);
            if (a.isPlatform()) {
                throw new IllegalArgumentException("address " + text + " is the platform's (address 0)");
            }
            return a.toString();
        }
        return SunSpotAddress.parse(text).toString();
    }

    private static void check(Map<String, String> options, List<String> types) {
        String door = options.get("door");
        if (door != null && !(types.contains("door") && (door.equals("outer") || door.equals("inner")))) {
            throw new IllegalArgumentException("door=outer|inner needs node type door");
        }
        String percent = options.get("percent");
        if (percent != null && !percent.matches("\\d{1,3}") || percent != null && Integer.parseInt(percent) > 100) {
            throw new IllegalArgumentException("percent must be 0..100");
        }
        if (options.containsKey("agent") && !types.contains("pet-collar") && !types.contains("person")) {
            throw new IllegalArgumentException("agent=<pet> needs node type pet-collar (agent=<wearer>: person)");
        }
        if (types.contains("person") && !options.containsKey("agent")) {
            throw new IllegalArgumentException("a person node needs agent=<the person of the scenario who wears it>");
        }
        if (options.containsKey("person") && !types.contains("person")) {
            throw new IllegalArgumentException("person=<name> needs node type person");
        }
    }
}
