package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.time.Instant;
import java.util.TreeMap;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.tinysep.api.service.MailStatus;

/**
 * The sending engine: a FIFO queue mirrored in a {@link MailSpool}, worked off one message at a time on its own
 * single thread. A failed attempt keeps the message at the head and retries with exponential back-off, so the
 * order is kept and the caller never waits. Every state change goes to {@link OutboxEvents}.
 */
final class Outbox implements AutoCloseable {

    private final ScheduledExecutorService executor;
    private final SmtpTransport transport;
    private final OutboxEvents events;
    private final Supplier<Instant> clock;
    private final TreeMap<Long, MailMessage> queue = new TreeMap<>(); // by id = sending order; outbox thread only
    private MailSettings settings; // outbox thread only
    private MailSpool spool;
    private Backoff backoff;
    private ScheduledFuture<?> pending; // the one pending attempt, immediate or after back-off; outbox thread only
    private long lastId;
    private volatile MailStatus status;
    private volatile int size;

    /** Loads the spool of {@code settings} and starts sending what it holds. */
    Outbox(MailSettings settings, SmtpTransport transport, OutboxEvents events, Supplier<Instant> clock) {
        this.transport = transport;
        this.events = events;
        this.clock = clock;
        this.executor = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "tinysep-mail");
            t.setDaemon(true);
            return t;
        });
        executor.execute(() -> apply(settings));
    }

    /** Queues a message and returns at once. */
    void send(String subject, String body) {
        Instant at = clock.get();
        try {
            executor.execute(() -> add(subject, body, at));
        } catch (RejectedExecutionException e) { // closed meanwhile: say so rather than drop it silently
            events.logged(new MailMessage(0, at, subject, body));
        }
    }

    /** Takes a new configuration; queued messages are kept (moved to a new spool folder if it changed). */
    void reconfigure(MailSettings next) {
        executor.execute(() -> apply(next));
    }

    /** Skips the current back-off delay and tries again at once. */
    void retryNow() {
        executor.execute(() -> {
            if (pending != null && pending.cancel(false)) {
                pending = null;
                kick();
            }
        });
    }

    MailStatus status() {
        return status;
    }

    int queued() {
        return size;
    }

    private void add(String subject, String body, Instant at) {
        lastId = Math.max(lastId + 1, at.toEpochMilli() * 1000);
        MailMessage m = new MailMessage(lastId, at, subject, body);
        if (!settings.configured()) {
            events.logged(m);
            return;
        }
        try {
            spool.write(m);
        } catch (IOException e) {
            events.problem("cannot write " + m + " to the spool " + spool.dir() + " (kept in memory only): " + e);
        }
        queue.put(m.id(), m);
        size = queue.size();
        events.queued(m);
        if (status != MailStatus.RETRYING) {
            status(MailStatus.SENDING, queue.size() + " queued");
        }
        kick();
    }

    /** Schedules an attempt now unless one is already pending (then the back-off it waits for is kept). */
    private void kick() {
        if (pending == null) {
            pending = executor.schedule(this::attempt, 0, TimeUnit.SECONDS);
        }
    }

    private void apply(MailSettings next) {
        MailSpool old = spool;
        settings = next;
        spool = new MailSpool(next.spoolDir());
        backoff = new Backoff(next.retryInitialSeconds(), next.retryMaxSeconds());
        if (pending != null) {
            pending.cancel(false);
            pending = null;
        }
        if (old != null && !old.dir().equals(spool.dir())) {
            queue.values().forEach(m -> old.moveTo(spool, m, events::problem));
        }
        for (MailMessage m : spool.load(events::problem)) {
            queue.putIfAbsent(m.id(), m);
            lastId = Math.max(lastId, m.id());
        }
        size = queue.size();
        if (!next.configured()) {
            status(MailStatus.NOT_CONFIGURED, queue.isEmpty() ? "" : queue.size() + " spooled, waiting for a host");
            return;
        }
        status(queue.isEmpty() ? MailStatus.IDLE : MailStatus.SENDING, queue.isEmpty() ? "" : queue.size() + " queued");
        if (!queue.isEmpty()) {
            kick();
        }
    }

    /** Sends the head of the queue; reschedules itself for the next message or, after a failure, a retry. */
    private void attempt() {
        pending = null;
        if (queue.isEmpty() || !settings.configured()) {
            return;
        }
        MailMessage m = queue.firstEntry().getValue();
        SmtpTransport.Result r = transport.send(settings, m);
        switch (r.outcome()) {
            case SENT, PARTIAL -> done(m, false, () -> events.sent(m, r.detail()));
            case REFUSED -> done(m, true, () -> events.givenUp(m, r.detail() + "; kept in " + spool.dir()
                    + "/failed"));
            case RETRY -> {
                long delay = backoff.fail();
                status(MailStatus.RETRYING, "attempt " + backoff.failures() + " failed: " + r.detail()
                        + "; next try in " + delay + " s, " + queue.size() + " queued");
                pending = executor.schedule(this::attempt, delay, TimeUnit.SECONDS);
            }
        }
    }

    private void done(MailMessage m, boolean refused, Runnable report) {
        queue.remove(m.id());
        size = queue.size();
        backoff.reset();
        try {
            if (refused) {
                spool.moveToFailed(m);
            } else {
                spool.delete(m);
            }
        } catch (IOException e) {
            events.problem("cannot remove finished " + m + " from the spool (it may be sent again): " + e);
        }
        report.run();
        if (queue.isEmpty()) {
            status(MailStatus.IDLE, "");
        } else {
            status(MailStatus.SENDING, queue.size() + " queued");
            kick();
        }
    }

    private void status(MailStatus next, String detail) {
        if (next != status || next == MailStatus.RETRYING) {
            status = next;
            events.statusChanged(next, detail);
        }
    }

    /** Stops the thread; queued messages stay in the spool for the next start. */
    @Override
    public void close() {
        executor.shutdownNow();
        try {
            executor.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
