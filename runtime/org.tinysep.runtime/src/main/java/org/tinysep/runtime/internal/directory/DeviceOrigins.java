package org.tinysep.runtime.internal.directory;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.tinysep.device.support.lifecycle.Safely;

/** The log origins a user means by a device or driver reference in {@code events --device D}. */
public final class DeviceOrigins {

    private DeviceOrigins() {
    }

    /**
     * @return the UIDs of the current devices and drivers {@code ref} names (UID, unique UID prefix, name ignoring
     *         case, node address), {@code node <address>} for such a device with a node address, and {@code ref} itself, so that
     *         devices removed since can be found by the UID the log shows
     */
    public static Set<String> of(String ref, Inventory inventory) {
        String q = ref == null ? "" : ref.strip();
        if (q.isEmpty()) {
            throw new IllegalArgumentException("--device needs a device uid or name");
        }
        Set<String> out = new LinkedHashSet<>();
        out.add(q);
        List<DeviceRecord> devices = inventory.devices();
        List<String> uids = devices.stream().map(DeviceRecord::uid).toList();
        List<String> byUid = uids.contains(q) ? List.of(q) : UidResolver.matches(q, uids);
        for (DeviceRecord d : devices) {
            String name = Safely.get(() -> d.device().name(), d.name());
            if ((byUid.size() == 1 && byUid.get(0).equals(d.uid())) || name.equalsIgnoreCase(q)
                    || d.name().equalsIgnoreCase(q) || d.node().address().equals(q)) {
                out.add(d.uid());
                if (!d.node().address().isEmpty()) {
                    out.add("node " + d.node().address());
                }
            }
        }
        Lookup.driversNamed(inventory, q).forEach(d -> out.add(d.uid()));
        return out;
    }
}
