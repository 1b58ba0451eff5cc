package org.tinysep.simulator.replay;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;

/**
 * A replay mapping file: which simulated node each recorded sensor becomes (format in README-replay.md). Lines are
 * {@code key = value} pairs separated by {@code ;}; blank lines and lines starting with {@code #} are ignored:
 * <pre>
 * allocate = 1.100
 * default  = pressure; type = window
 * sensor   = Maindoor; node = amica 1.20; type = door; doorKind = OUTER; room = Entrance
 * </pre>
 * Built-in defaults by kind: motion → movement, door → window (door OUTER where the name or room says it leads
 * outside), pressure → presence-seat (presence-bed where the name or room says bed), flush → presence-flush,
 * electric → presence-appliance, other → window (README-replay.md says why; {@link NameHints}).
 */
public final class SensorMapping {

    /** A sensor line; null fields mean "not given". */
    record Entry(AmicaAddress address, AmicaNodeType type, String room, String doorKind, String name) {
    }

    /** A default line: node type (and door kind) for a sensor kind. */
    record Default(AmicaNodeType type, String doorKind) {
    }

    private static final Map<Kind, Default> BUILT_IN = Collections.unmodifiableMap(builtIn());

    private final Map<String, Entry> entries;
    private final Map<Kind, Default> defaults;
    private final AmicaAddress firstFree;

    SensorMapping(Map<String, Entry> entries, Map<Kind, Default> defaults, AmicaAddress firstFree) {
        this.entries = Collections.unmodifiableMap(new LinkedHashMap<>(entries));
        this.defaults = new EnumMap<>(defaults);
        this.firstFree = firstFree;
    }

    /** @return a mapping without sensor lines: built-in defaults, addresses allocated from 1.100 */
    public static SensorMapping defaults() {
        return new SensorMapping(Map.of(), builtInDefaults(), new AmicaAddress(1, 100));
    }

    /**
     * @param file a mapping file (UTF-8)
     * @return the mapping
     * @throws IOException if the file cannot be read
     * @throws ReplayFormatException naming file and line for a malformed line or a duplicate sensor or address
     */
    public static SensorMapping read(Path file) throws IOException, ReplayFormatException {
        return parse(Files.readAllLines(file, StandardCharsets.UTF_8), file.getFileName().toString());
    }

    /**
     * @param resource file name under the class-path folder {@code /replay/}, e.g. {@code ordonez-a.mapping}
     * @return the mapping shipped with the simulator
     * @throws IOException if there is no such resource
     * @throws ReplayFormatException if it is malformed
     */
    public static SensorMapping fromResource(String resource) throws IOException, ReplayFormatException {
        try (java.io.InputStream in = SensorMapping.class.getResourceAsStream("/replay/" + resource)) {
            if (in == null) {
                throw new IOException("no mapping resource /replay/" + resource);
            }
            return parse(new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList(), resource);
        }
    }

    /** Parses mapping lines; {@code name} is used in messages. */
    public static SensorMapping parse(List<String> lines, String name) throws ReplayFormatException {
        return new MappingParser(name, builtInDefaults()).parse(lines);
    }

    /** @return true if the file has a {@code sensor =} line for this sensor */
    public boolean isMapped(String sensor) {
        return entries.containsKey(sensor);
    }

    /** @return the sensors named in the file, in file order */
    public List<String> mappedSensors() {
        return List.copyOf(entries.keySet());
    }

    /** @return the first address tried for sensors without a {@code node}; used addresses are skipped */
    public AmicaAddress firstFree() {
        return firstFree;
    }

    /** @return the explicit addresses of the file (may be incomplete: entries without node are allocated later) */
    List<AmicaAddress> explicitAddresses() {
        return entries.values().stream().map(Entry::address).filter(a -> a != null).toList();
    }

    /**
     * @param sensor   recorded sensor name
     * @param room     recorded room (used when the file gives none)
     * @param kind     recorded kind (selects the default type)
     * @param address  address to use when the file gives none (from the allocator)
     * @return the node the sensor becomes
     */
    NodeSpec resolve(String sensor, String room, Kind kind, AmicaAddress address) {
        Entry e = entries.get(sensor);
        Default d = hinted(sensor, room, kind);
        AmicaNodeType type = e != null && e.type() != null ? e.type() : d.type();
        String doorKind = e != null && e.doorKind() != null ? e.doorKind()
                : type != AmicaNodeType.DOOR ? "" : d.type() == AmicaNodeType.DOOR ? d.doorKind() : "INNER";
        return new NodeSpec(sensor, NodeSpec.AMICA, e != null && e.address() != null ? e.address() : address, type,
                e != null && e.room() != null ? e.room() : room, doorKind,
                e != null && e.name() != null ? e.name() : sensor);
    }

    /**
     * @return the kind's default; where the file has no default line for the kind, the built-in one read with the
     *         sensor's name and room ({@link NameHints}): a door that leads outside is an OUTER door, any other door
     *         contact a window node (the platform's Door device defaults to OUTER and a replay cannot configure it;
     *         a window is "activity that says nothing about leaving"), a mat that says bed a bed
     */
    private Default hinted(String sensor, String room, Kind kind) {
        Default d = defaults.get(kind);
        if (d != BUILT_IN.get(kind)) {
            return d;
        }
        if (kind == Kind.DOOR) {
            return "OUTER".equals(NameHints.doorKind(sensor, room)) ? new Default(AmicaNodeType.DOOR, "OUTER")
                    : new Default(AmicaNodeType.WINDOW, "");
        }
        return kind == Kind.PRESSURE ? new Default(NameHints.pressureType(sensor, room), "") : d;
    }

    /** @return true if a node for this sensor needs an allocated address */
    boolean needsAddress(String sensor) {
        Entry e = entries.get(sensor);
        return e == null || e.address() == null;
    }

    /** @return a modifiable copy of the built-in defaults (the same instances: a file's default line replaces one) */
    static Map<Kind, Default> builtInDefaults() {
        return new EnumMap<>(BUILT_IN);
    }

    private static Map<Kind, Default> builtIn() {
        Map<Kind, Default> d = new EnumMap<>(Kind.class);
        d.put(Kind.MOTION, new Default(AmicaNodeType.MOVEMENT, ""));
        d.put(Kind.DOOR, new Default(AmicaNodeType.DOOR, "INNER"));
        // a pressure mat holds a person but whether it is a bed is unknown: seat (someone is here, no
        // sleep state claimed); a file that knows better says presence-bed
        d.put(Kind.PRESSURE, new Default(AmicaNodeType.PRESENCE_SEAT, ""));
        d.put(Kind.FLUSH, new Default(AmicaNodeType.PRESENCE_FLUSH, ""));
        d.put(Kind.ELECTRIC, new Default(AmicaNodeType.PRESENCE_APPLIANCE, ""));
        d.put(Kind.OTHER, new Default(AmicaNodeType.WINDOW, ""));
        return d;
    }
}
