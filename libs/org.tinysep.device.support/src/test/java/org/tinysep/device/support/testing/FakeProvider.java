package org.tinysep.device.support.testing;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.device.Connection;

/**
 * For unit tests of services: the listener side of a hand-written provider; a closed connection stops delivery.
 * A fake provider extends it and implements its provider interface.
 *
 * @param <L> the listener interface
 */
public class FakeProvider<L> {

    public final String uid;
    /** The connected listeners; a fake calls them like a device does. */
    public final List<L> listeners = new ArrayList<>();

    public FakeProvider(String uid) {
        this.uid = uid;
    }

    public String deviceUid() {
        return uid;
    }

    public Connection connect(L l) {
        listeners.add(l);
        return new Connection() {
            @Override
            public void close() {
                listeners.remove(l);
            }

            @Override
            public boolean isOpen() {
                return listeners.contains(l);
            }
        };
    }
}
