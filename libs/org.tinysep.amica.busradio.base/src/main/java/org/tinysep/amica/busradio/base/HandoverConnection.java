package org.tinysep.amica.busradio.base;

import java.util.concurrent.atomic.AtomicBoolean;
import org.tinysep.api.device.Connection;

/** A bus device listener's connection; closing it tells the {@link Handover} that a replacement may follow. */
final class HandoverConnection implements Connection {

    private final Connection connection;
    private final Handover handover;
    private final AtomicBoolean closed = new AtomicBoolean();

    /** @param handover also the lock the bus device holds around it */
    HandoverConnection(Connection connection, Handover handover) {
        this.connection = connection;
        this.handover = handover;
    }

    @Override
    public void close() {
        if (closed.compareAndSet(false, true) && connection.isOpen()) {
            // one step under the lock payload delivery holds: a payload is either delivered to the leaving listener
            // or held for its replacement, never neither (lost) nor both (seen twice). Safe: closing a listener
            // list's handle takes no lock.
            synchronized (handover) {
                connection.close();
                handover.listenerLeft();
            }
        }
    }

    @Override
    public boolean isOpen() {
        return connection.isOpen();
    }
}
