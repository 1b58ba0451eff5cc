package org.tinysep.alerts.internal;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertListener;
import org.tinysep.api.device.Connection;
import org.tinysep.device.support.lifecycle.Listeners;

/** Tells the alert listeners of each change, in order, on a thread of its own (never the caller's). */
final class FanOut implements AutoCloseable {

    private final Listeners<AlertListener> listeners = new Listeners<>(AlertLog.ORIGIN);
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> new Thread(r, "tinysep-alerts"));

    Connection add(AlertListener l) {
        return listeners.add(l);
    }

    void changed(Alert a) {
        try {
            thread.execute(() -> listeners.fire(l -> l.alertChanged(a)));
        } catch (RejectedExecutionException e) {
            // stopping: the change is saved, the listeners are going away with the service
        }
    }

    @Override
    public void close() {
        thread.shutdown();
        try {
            thread.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        listeners.closeAll();
    }
}
