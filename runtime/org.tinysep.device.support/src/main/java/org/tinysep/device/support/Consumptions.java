package org.tinysep.device.support;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.ConnectionInfo;

/**
 * The connections a device holds as a consumer, with whether each is vital (thesis 3.3: a device that loses
 * all its vital connections removes itself).
 */
public final class Consumptions {

    private record Held(ConnectionInfo info, Connection handle) {
    }

    private final Map<String, Held> held = new LinkedHashMap<>();

    private static String key(String interfaceName, String providerUid) {
        return interfaceName + '\u0000' + providerUid;
    }

    /** Records an open connection. A previous one under the same key is closed. */
    public void add(String interfaceName, String providerUid, boolean vital, Connection handle) {
        Held old;
        synchronized (held) {
            old = held.put(key(interfaceName, providerUid),
                    new Held(new ConnectionInfo(interfaceName, providerUid, vital), handle));
        }
        if (old != null) {
            old.handle.close();
        }
    }

    /** Closes and forgets one connection. @return whether it was held */
    public boolean remove(String interfaceName, String providerUid) {
        Held old;
        synchronized (held) {
            old = held.remove(key(interfaceName, providerUid));
        }
        if (old == null) {
            return false;
        }
        old.handle.close();
        return true;
    }

    /** @return whether at least one vital connection is still held */
    public boolean hasVital() {
        synchronized (held) {
            return held.values().stream().anyMatch(h -> h.info.vital());
        }
    }

    /** @return the held connections in the order they were made */
    public List<ConnectionInfo> infos() {
        synchronized (held) {
            List<ConnectionInfo> out = new ArrayList<>(held.size());
            held.values().forEach(h -> out.add(h.info));
            return out;
        }
    }

    /** Closes every connection. */
    public void closeAll() {
        List<Held> all;
        synchronized (held) {
            all = new ArrayList<>(held.values());
            held.clear();
        }
        all.forEach(h -> h.handle.close());
    }
}
