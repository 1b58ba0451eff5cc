package org.tinysep.api.backup;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * The backup of one driver or device (thesis 3.7): who it is, its user settings and what its driver needs to
 * re-create it as it was.
 *
 * @param uid         the component's UID (stable across restarts, see {@code Uids})
 * @param kind        driver or device
 * @param driverUid   the UID of the owning driver (a driver's own UID for a driver)
 * @param driverName  the owning driver's name, e.g. {@code BusRadioAmicaUdp}
 * @param type        the device type (the driver name for a driver)
 * @param name        the name shown to the user
 * @param parameters  user settings, key to value as {@code setParameter} accepts them (e.g. {@code room} to a room
 *                    UID), in the order they are applied; never {@code name}
 * @param nodeAddress the hardware node address a bus device stands for, or empty
 * @param nodeTypes   the node types the bus device announced, or empty
 * @param lastSeen    when the node or component was last heard from, or null
 * @param state       free runtime state the owner wants back (e.g. keep-alive fields, last activity per room)
 * @param savedAt     when the owner made this backup
 */
public record ComponentBackup(String uid, ComponentKind kind, String driverUid, String driverName, String type,
        String name, Map<String, String> parameters, String nodeAddress, List<String> nodeTypes, Instant lastSeen,
        Map<String, String> state, Instant savedAt) {

    public ComponentBackup {
        Objects.requireNonNull(uid, "uid");
        Objects.requireNonNull(kind, "kind");
        driverUid = Objects.requireNonNullElse(driverUid, "");
        driverName = Objects.requireNonNullElse(driverName, "");
        type = Objects.requireNonNullElse(type, "");
        name = Objects.requireNonNullElse(name, "");
        parameters = parameters == null ? Map.of() : copy(parameters);
        nodeAddress = Objects.requireNonNullElse(nodeAddress, "");
        nodeTypes = nodeTypes == null ? List.of() : List.copyOf(nodeTypes);
        state = state == null ? Map.of() : copy(state);
        Objects.requireNonNull(savedAt, "savedAt");
    }

    private static Map<String, String> copy(Map<String, String> m) {
        Map<String, String> out = new LinkedHashMap<>();
        m.forEach((k, v) -> out.put(Objects.requireNonNull(k, "key"), Objects.requireNonNullElse(v, "")));
        return java.util.Collections.unmodifiableMap(out);
    }
}
