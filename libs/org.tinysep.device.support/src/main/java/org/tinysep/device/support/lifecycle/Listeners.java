package org.tinysep.device.support.lifecycle;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Connection;

/**
 * The listeners connected to one provider. Dispatch is synchronous on the caller's thread; a listener that
 * throws is logged and skipped so delivery to the others goes on (docs/architecture.md, "Threading").
 *
 * @param <L> the listener type
 */
public final class Listeners<L> {

    private static final Logger LOG = LoggerFactory.getLogger(Listeners.class);

    private final String owner;
    private final CopyOnWriteArrayList<Handle> handles = new CopyOnWriteArrayList<>();
    private final AtomicLong failures = new AtomicLong();

    /** @param owner names the provider in log messages, e.g. its device uid */
    public Listeners(String owner) {
        this.owner = owner;
    }

    /** Connects a listener; the returned handle disconnects it. */
    public Connection add(L listener) {
        if (listener == null) {
            throw new IllegalArgumentException("listener must not be null");
        }
        Handle h = new Handle(listener);
        handles.add(h);
        return h;
    }

    /** Calls every connected listener in connection order. */
    public void fire(Consumer<? super L> call) {
        for (Handle h : handles) {
            if (!h.open.get()) {
                continue;
            }
            try {
                call.accept(h.listener);
            } catch (RuntimeException | LinkageError e) {
                long n = failures.incrementAndGet();
                LOG.warn("Listener {} of {} failed ({} failures so far): {}", h.listener.getClass().getName(), owner,
                        n, e.toString());
                LOG.debug("Listener failure detail", e);
            }
        }
    }

    /** @return the number of open connections */
    public int size() {
        return handles.size();
    }

    /** @return the listeners connected now, in connection order (e.g. to name the devices that depend on a node) */
    public List<L> connected() {
        List<L> out = new ArrayList<>();
        for (Handle h : handles) {
            if (h.open.get()) {
                out.add(h.listener);
            }
        }
        return out;
    }

    /** @return how many listener calls threw since creation */
    public long failures() {
        return failures.get();
    }

    /** Closes every connection, e.g. when the provider goes away. */
    public void closeAll() {
        for (Handle h : handles) {
            h.close();
        }
    }

    private final class Handle implements Connection {
        final L listener;
        final AtomicBoolean open = new AtomicBoolean(true);

        Handle(L listener) {
            this.listener = listener;
        }

        @Override
        public void close() {
            if (open.compareAndSet(true, false)) {
                handles.remove(this);
            }
        }

        @Override
        public boolean isOpen() {
            return open.get();
        }
    }
}
