package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.time.Clock;
import java.time.Instant;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.tinysep.api.service.MailStatus;
import org.tinysep.device.support.time.Backoff;

/**
 * The sending engine: a FIFO queue mirrored in a {@link MailSpool}, worked off one message at a time on its own
 * single thread. A temporary failure keeps the message at the head and retries with exponential back-off (what
 * happens after an attempt is {@link Delivery}'s job), so the order is kept and the caller never waits.
 */
final class Outbox implements AutoCloseable {

    private final ScheduledExecutorService executor;
    private final OutboxEvents events;
    private final Supplier<Instant> clock;
    private final Delivery delivery;
    private final TreeMap<Long, MailMessage> queue = new TreeMap<>(); // by id = sending order; outbox thread only
    private final Map<Long, Backoff> backoffs = new HashMap<>(); // of messages that failed; outbox thread only
    private final Map<Long, Long> due = new HashMap<>(); // System.nanoTime of their next try; outbox thread only
    private long serverDue; // no message is tried before this System.nanoTime (server-wide failure); outbox thread
    private MailSettings settings; // outbox thread only
    private MailSpool spool;
    private ScheduledFuture<?> pending; // the one pending attempt, immediate or after back-off; outbox thread only
    private final java.util.concurrent.atomic.AtomicLong lastId = new java.util.concurrent.atomic.AtomicLong();
    private volatile MailStatus status;
    private volatile int size;

    /**
     * Loads the spool of {@code settings} and starts sending what it holds.
     *
     * @param clock the platform clock (time stamps, "retrying at"); {@code wall} the computer's clock (give-up age)
     */
    Outbox(MailSettings settings, SmtpTransport transport, OutboxEvents events, Supplier<Instant> clock, Clock wall) {
        this.events = events;
        this.clock = clock;
        this.delivery = new Delivery(transport, events, clock, wall);
        this.executor = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "tinysep-mail");
            t.setDaemon(true);
            return t;
        });
        executor.execute(() -> apply(settings));
    }

    /**
     * Queues a message and returns at once.
     *
     * @param to the addresses; empty = the configured recipients
     * @return the message's id (increasing: the sending order)
     */
    long send(java.util.List<String> to, String subject, String body) {
        Instant at = clock.get();
        long id = lastId.updateAndGet(last -> Math.max(last + 1, at.toEpochMilli() * 1000));
        MailMessage m = new MailMessage(id, at, subject, body, java.util.List.of(), java.util.List.of(), null, to);
        try {
            executor.execute(() -> add(m));
        } catch (RejectedExecutionException e) { // closed meanwhile: say so rather than drop it silently
            events.logged(m);
        }
        return id;
    }

    /** Takes a new configuration; queued messages are kept (moved to a new spool folder if it changed). */
    void reconfigure(MailSettings next) {
        executor.execute(() -> apply(next));
    }

    /** Skips the current back-off delay and tries again at once. */
    void retryNow() {
        executor.execute(() -> {
            due.clear();
            serverDue = 0;
            kick();
        });
    }

    MailStatus status() {
        return status;
    }

    int queued() {
        return size;
    }

    private void add(MailMessage m) {
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
        events.queued(m, m.recipients(settings.recipients()));
        if (status != MailStatus.RETRYING) {
            status(MailStatus.SENDING, queue.size() + " queued");
        }
        kick();
    }

    /** Looks for due messages now (a message waiting for its retry keeps its own time). */
    private void kick() {
        if (pending != null) {
            pending.cancel(false);
        }
        pending = executor.schedule(this::attempt, 0, TimeUnit.SECONDS);
    }

    private void apply(MailSettings next) {
        MailSpool old = spool;
        settings = next;
        spool = new MailSpool(next.spoolDir());
        delivery.configure(next, spool);
        backoffs.clear();
        due.clear();
        serverDue = 0;
        if (pending != null) {
            pending.cancel(false);
            pending = null;
        }
        if (old != null && !old.dir().equals(spool.dir())) {
            queue.values().forEach(m -> old.moveTo(spool, m, events::problem));
            delivery.moveNotice(old);
        }
        for (MailMessage m : spool.load(events::problem)) {
            queue.putIfAbsent(m.id(), m);
            lastId.accumulateAndGet(m.id(), Math::max);
        }
        size = queue.size();
        events.undelivered(spool.notice());
        if (!next.configured()) {
            status(MailStatus.NOT_CONFIGURED, queue.isEmpty() ? "" : queue.size() + " spooled, waiting for a host");
            return;
        }
        status(queue.isEmpty() ? MailStatus.IDLE : MailStatus.SENDING, queue.isEmpty() ? "" : queue.size() + " queued");
        if (!queue.isEmpty()) {
            kick();
        }
    }

    /**
     * Sends the first message that is due, in queue order. A failure about particular recipients (a full mailbox)
     * delays only that message; a server-wide one (no connection, 4xx to MAIL) holds the whole queue, so the order
     * is kept. Then reschedules itself for the next due message.
     */
    private void attempt() {
        pending = null;
        if (queue.isEmpty() || !settings.configured()) {
            return;
        }
        long now = System.nanoTime();
        MailMessage m = serverDue - now > 0 ? null : queue.values().stream()
                .filter(x -> due.getOrDefault(x.id(), now) - now <= 0).findFirst().orElse(null);
        if (m != null) {
            Delivery.Next next = delivery.attempt(m, backoffs.getOrDefault(m.id(),
                    Backoff.ofSeconds(settings.retryInitialSeconds(), settings.retryMaxSeconds())));
            long at = System.nanoTime() + TimeUnit.SECONDS.toNanos(next.delaySeconds());
            serverDue = next.serverWide() ? at : 0;
            if (next.retry() != null) {
                queue.put(m.id(), next.retry());
                backoffs.put(m.id(), next.backoff());
                due.put(m.id(), at);
                status(MailStatus.RETRYING, next.detail());
            } else {
                queue.remove(m.id());
                backoffs.remove(m.id());
                due.remove(m.id());
                size = queue.size();
                if (due.isEmpty()) {
                    status(queue.isEmpty() ? MailStatus.IDLE : MailStatus.SENDING,
                            queue.isEmpty() ? "" : queue.size() + " queued");
                }
            }
        }
        if (!queue.isEmpty()) {
            long t = System.nanoTime();
            long soonest = Math.max(serverDue - t, queue.keySet().stream().mapToLong(id -> due.getOrDefault(id, t) - t)
                    .min().orElseThrow());
            pending = executor.schedule(this::attempt, Math.max(0, soonest), TimeUnit.NANOSECONDS);
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
