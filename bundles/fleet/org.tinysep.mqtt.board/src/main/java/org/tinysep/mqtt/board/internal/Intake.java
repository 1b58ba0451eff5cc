package org.tinysep.mqtt.board.internal;

import java.time.Clock;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.Iterator;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Between the MQTT client's callback and the {@link Board}: the callback only queues (never blocks, so the client
 * keeps reading), one worker applies the messages taking one flat's message at a time in turn (round robin), so a
 * flat flooding the board delays only itself. Each flat's queue holds at most {@link #PER_FLAT} messages; when a
 * flood fills it, its oldest non-alert message is dropped (the retained state topics are re-sent on the next
 * change anyway) and counted on that flat.
 */
final class Intake implements AutoCloseable {

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(Intake.class);

    static final int PER_FLAT = 512;

    /** Told after each message was applied, on the worker (the load test's clock of "visible on the board"). */
    interface Applied {
        void applied(String topic, byte[] payload, boolean changed);
    }

    private record Message(String topic, byte[] payload) {
        boolean alert() {
            return topic.contains("/alert/");
        }
    }

    private final Board board;
    private final Clock clock;
    private final Applied applied;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "tinysep-board-intake");
        t.setDaemon(true);
        return t;
    });
    private final Map<String, ArrayDeque<Message>> queues = new HashMap<>();
    private final ArrayDeque<String> turn = new ArrayDeque<>();
    private final AtomicLong dropped = new AtomicLong();
    private boolean draining;

    Intake(Board board, Clock clock, Applied applied) {
        this.board = board;
        this.clock = clock;
        this.applied = applied;
    }

    void offer(String topic, byte[] payload) {
        String flat = flatOf(topic);
        Message m = new Message(topic, payload);
        boolean start;
        synchronized (this) {
            ArrayDeque<Message> q = queues.computeIfAbsent(flat, k -> new ArrayDeque<>());
            if (q.size() >= PER_FLAT) {
                dropOne(q);
                dropped.incrementAndGet();
                board.find(flat).ifPresent(f -> f.dropped(1));
            }
            q.add(m);
            if (q.size() == 1) {
                turn.add(flat);
            }
            start = !draining;
            draining = true;
        }
        if (start) {
            worker.execute(this::drain);
        }
    }

    private static void dropOne(ArrayDeque<Message> q) {
        for (Iterator<Message> it = q.iterator(); it.hasNext();) {
            if (!it.next().alert()) {
                it.remove();
                return;
            }
        }
        q.poll();
    }

    private void drain() {
        while (true) {
            Message m;
            synchronized (this) {
                String flat = turn.poll();
                if (flat == null) {
                    draining = false;
                    return;
                }
                ArrayDeque<Message> q = queues.get(flat);
                m = q.poll();
                if (q.isEmpty()) {
                    queues.remove(flat);
                } else {
                    turn.add(flat);
                }
            }
            try {
                boolean changed = board.accept(m.topic(), m.payload(), clock.instant());
                if (applied != null) {
                    applied.applied(m.topic(), m.payload(), changed);
                }
            } catch (RuntimeException e) { // a fault of the board, not of the message: keep going, say so
                LOG.error("Central board: message on {} not applied", m.topic(), e);
            }
        }
    }

    long dropped() {
        return dropped.get();
    }

    private String flatOf(String topic) {
        String rest = topic.startsWith(board.prefix() + "/") ? topic.substring(board.prefix().length() + 1) : topic;
        int slash = rest.indexOf('/');
        return slash < 0 ? rest : rest.substring(0, slash);
    }

    @Override
    public void close() {
        worker.shutdownNow();
        try {
            worker.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
