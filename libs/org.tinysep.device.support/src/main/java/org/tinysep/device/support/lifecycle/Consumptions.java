package org.tinysep.device.support.lifecycle;

import java.util.ArrayList;
import java.util.HashMap;
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
    /** The keys held per provider device UID: a provider that goes costs its own connections only. */
    private final Map<String, List<String>> byProvider = new HashMap<>();
    private int vital;

    private static String key(String interfaceName, String providerUid) {
        return interfaceName + '\u0000' + providerUid;
    }

    /** Records an open connection. A previous one under the same key is closed. */
    public void add(String interfaceName, String providerUid, boolean vital, Connection handle) {
        Held old;
        String key = key(interfaceName, providerUid);
        synchronized (held) {
            old = held.put(key, new Held(new ConnectionInfo(interfaceName, providerUid, vital), handle));
            if (old == null) {
                byProvider.computeIfAbsent(providerUid, p -> new ArrayList<>(1)).add(key);
            } else if (old.info.vital()) {
                this.vital--;
            }
            if (vital) {
                this.vital++;
            }
        }
        if (old != null) {
            old.handle.close();
        }
    }

    /** Closes and forgets one connection. @return whether it was held */
    public boolean remove(String interfaceName, String providerUid) {
        Held old;
        String key = key(interfaceName, providerUid);
        synchronized (held) {
            old = held.remove(key);
            if (old != null) {
                List<String> keys = byProvider.get(providerUid);
                keys.remove(key);
                if (keys.isEmpty()) {
                    byProvider.remove(providerUid);
                }
                if (old.info.vital()) {
                    vital--;
                }
            }
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
            return vital > 0;
        }
    }

    /** @return the connections held to one provider device (read from an index: not a scan of all) */
    public List<ConnectionInfo> to(String providerUid) {
        synchronized (held) {
            List<String> keys = byProvider.get(providerUid);
            if (keys == null) {
                return List.of();
            }
            List<ConnectionInfo> out = new ArrayList<>(keys.size());
            keys.forEach(k -> out.add(held.get(k).info));
            return out;
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
            byProvider.clear();
            vital = 0;
        }
        all.forEach(h -> h.handle.close());
    }
}
