package org.tinysep.simulator.replay;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;

/** Parses the lines of a mapping file into a {@link SensorMapping}; one instance per file. */
final class MappingParser {

    private static final Set<String> SENSOR_KEYS = Set.of("sensor", "node", "type", "room", "doorkind", "name");
    private static final Set<String> DEFAULT_KEYS = Set.of("default", "type", "doorkind");

    private final String file;
    private final Map<Kind, SensorMapping.Default> defaults;
    private final Map<String, SensorMapping.Entry> entries = new LinkedHashMap<>();
    private final Map<AmicaAddress, String> usedBy = new HashMap<>();
    private AmicaAddress firstFree = new AmicaAddress(1, 100);
    private int line;

    MappingParser(String file, Map<Kind, SensorMapping.Default> defaults) {
        this.file = file;
        this.defaults = defaults;
    }

    SensorMapping parse(List<String> lines) throws ReplayFormatException {
        for (line = 1; line <= lines.size(); line++) {
            String text = Csv.stripBom(lines.get(line - 1)).strip();
            if (text.isEmpty() || text.startsWith("#")) {
                continue;
            }
            Map<String, String> kv = pairs(text);
            if (kv.containsKey("sensor")) {
                sensor(kv);
            } else if (kv.containsKey("default")) {
                defaultLine(kv);
            } else if (kv.containsKey("allocate") && kv.size() == 1) {
                firstFree = address(kv.get("allocate"));
            } else {
                throw error("expected a 'sensor = ...', 'default = <kind>; type = ...' or 'allocate = NG.ADDR' line");
            }
        }
        return new SensorMapping(entries, defaults, firstFree);
    }

    private void sensor(Map<String, String> kv) throws ReplayFormatException {
        check(kv, SENSOR_KEYS);
        String sensor = kv.get("sensor");
        if (sensor.isEmpty() || entries.containsKey(sensor)) {
            throw error(sensor.isEmpty() ? "sensor name is empty" : "sensor '" + sensor + "' is mapped twice");
        }
        AmicaAddress address = null;
        if (kv.containsKey("node")) {
            String[] node = kv.get("node").split("\\s+");
            if (node.length != 2 || !node[0].equals(NodeSpec.AMICA)) {
                throw error("node '" + kv.get("node") + "': expected 'amica NG.ADDR', e.g. 'amica 1.41' "
                        + "(only the AmICA family is supported)");
            }
            address = address(node[1]);
            String other = usedBy.putIfAbsent(address, sensor);
            if (other != null) {
                throw error("address " + address + " of '" + sensor + "' is already used by '" + other + "'");
            }
        }
        AmicaNodeType type = kv.containsKey("type") ? type(kv.get("type")) : null;
        String doorKind = kv.containsKey("doorkind") ? doorKind(kv.get("doorkind"), type) : null;
        entries.put(sensor, new SensorMapping.Entry(address, type, kv.get("room"), doorKind, kv.get("name")));
    }

    private void defaultLine(Map<String, String> kv) throws ReplayFormatException {
        check(kv, DEFAULT_KEYS);
        Kind kind;
        try {
            kind = Kind.parse(kv.get("default"));
        } catch (IllegalArgumentException e) {
            throw error(e.getMessage());
        }
        if (!kv.containsKey("type")) {
            throw error("a default line needs 'type = ...'");
        }
        AmicaNodeType type = type(kv.get("type"));
        String doorKind = type != AmicaNodeType.DOOR ? "" : kv.containsKey("doorkind")
                ? doorKind(kv.get("doorkind"), type) : "INNER";
        defaults.put(kind, new SensorMapping.Default(type, doorKind));
    }

    private Map<String, String> pairs(String text) throws ReplayFormatException {
        Map<String, String> kv = new LinkedHashMap<>();
        for (String part : text.split(";")) {
            if (part.isBlank()) {
                continue;
            }
            int eq = part.indexOf('=');
            if (eq < 0) {
                throw error("'" + part.strip() + "' is not 'key = value'");
            }
            String key = part.substring(0, eq).strip().toLowerCase(Locale.ROOT);
            if (kv.put(key, part.substring(eq + 1).strip()) != null) {
                throw error("key '" + key + "' given twice");
            }
        }
        return kv;
    }

    private void check(Map<String, String> kv, Set<String> allowed) throws ReplayFormatException {
        for (String key : kv.keySet()) {
            if (!allowed.contains(key)) {
                throw error("unknown key '" + key + "'; allowed here: "
                        + String.join(", ", allowed.stream().sorted().toList()));
            }
        }
    }

    private AmicaNodeType type(String name) throws ReplayFormatException {
        AmicaNodeType t = AmicaNodeType.fromTypeName(name.toLowerCase(Locale.ROOT)).orElse(null);
        if (t == null || !NodeSpec.isReplayable(t)) {
            throw error("type '" + name + "': expected " + NodeSpec.REPLAYABLE);
        }
        return t;
    }

    private String doorKind(String value, AmicaNodeType type) throws ReplayFormatException {
        String v = value.toUpperCase(Locale.ROOT);
        if ((type != null && type != AmicaNodeType.DOOR) || !(v.equals("OUTER") || v.equals("INNER"))) {
            throw error("doorKind '" + value + "': only for 'type = door', and OUTER or INNER");
        }
        return v;
    }

    private AmicaAddress address(String text) throws ReplayFormatException {
        try {
            AmicaAddress a = AmicaAddress.parse(text);
            if (a.isPlatform()) {
                throw error("address " + a + " is the platform's; nodes use 1..255");
            }
            return a;
        } catch (IllegalArgumentException e) {
            throw error(e.getMessage());
        }
    }

    private ReplayFormatException error(String reason) {
        return new ReplayFormatException(file, line, reason);
    }
}
