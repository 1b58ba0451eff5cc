package org.tinysep.sms.internal;

import java.io.IOException;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardWatchEventKinds;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/**
 * Watches gammu-smsd's {@code inbox/} (inotify on Linux, through java.nio's WatchService) and says when something
 * arrived, so the channel reads the inbox at once instead of looking every second. One thread of its own, blocked
 * while nothing happens; {@link #close} ends it. {@link #watch} is called again on each look: the inbox may appear
 * later (gammu-smsd set up while TinySEP runs) or be re-created.
 */
final class InboxWatch implements AutoCloseable {

    private final Runnable arrived;
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> new Thread(r, "tinysep-sms-inbox"));
    private WatchService service;
    private volatile WatchKey key;

    /** @param arrived told (on the watch's thread) when a file was created in or moved into the inbox */
    InboxWatch(Runnable arrived) {
        this.arrived = arrived;
    }

    /**
     * Watches {@code inbox} unless it does already.
     *
     * @return whether the inbox is watched now (false: it does not exist, or the system cannot watch it)
     */
    synchronized boolean watch(Path inbox) {
        WatchKey k = key;
        if (k != null && k.isValid()) {
            return true;
        }
        if (!Files.isDirectory(inbox) || thread.isShutdown()) {
            return false;
        }
        try {
            if (service == null) {
                service = FileSystems.getDefault().newWatchService();
                WatchService s = service;
                thread.execute(() -> take(s));
            }
            key = inbox.register(service, StandardWatchEventKinds.ENTRY_CREATE,
                    StandardWatchEventKinds.ENTRY_MODIFY);
            return true;
        } catch (IOException | RuntimeException e) {
            key = null;
            return false;
        }
    }

    private void take(WatchService s) {
        try {
            while (true) {
                WatchKey k = s.take();
                k.pollEvents();
                k.reset();
                arrived.run();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ClosedWatchServiceException e) {
            // closed: the channel went
        }
    }

    @Override
    public synchronized void close() {
        thread.shutdownNow();
        try {
            if (service != null) {
                service.close();
            }
            thread.awaitTermination(2, TimeUnit.SECONDS);
        } catch (IOException e) {
            // nothing left to watch
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
