package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.time.Instant;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.device.support.time.Backoff;

/**
 * The bridge's side of the link, on the bridge's thread: what the broker's answers do (connected: publish the
 * outbox; failed or lost: the status in words and the next attempt after 1, 2, 4 … 30 s; published: the outbox
 * learns it; a command: carried out or refused, counted, answered) and the figures of the bridge's device.
 */
final class Session implements Link.Events {

    private static final Logger LOG = LoggerFactory.getLogger(Bridge.class);
    private static final long MAX_WAIT_SECONDS = 30;

    private final Settings settings;
    private final ScheduledExecutorService executor;
    private final Supplier<Instant> clock;
    private final BiConsumer<DeviceStatus.State, String> status;
    private final Consumer<Figures> figures;
    private final Outbox outbox;
    private final Commands commands;
    private final CommandGuard guard;
    private final DeviceScan scan;
    private Link link;
    private int connectedGeneration = -1;
    /** Reconnect waits: 1 s after the first failure, doubled up to {@link #MAX_WAIT_SECONDS}. */
    private Backoff backoff = Backoff.ofSeconds(1, MAX_WAIT_SECONDS);
    private String lastProblem = "";
    private long accepted;
    private long rejected;
    private String linkWords = "connecting";

    Session(Settings settings, ScheduledExecutorService executor, Supplier<Instant> clock,
            BiConsumer<DeviceStatus.State, String> status, Consumer<Figures> figures, Outbox outbox,
            Commands commands, CommandGuard guard, DeviceScan scan) {
        this.settings = settings;
        this.executor = executor;
        this.clock = clock;
        this.status = status;
        this.figures = figures;
        this.outbox = outbox;
        this.commands = commands;
        this.guard = guard;
        this.scan = scan;
    }

    /** The link whose answers this session takes; its first attempt starts now. */
    void start(Link l) {
        this.link = l;
        status.accept(DeviceStatus.State.OFFLINE, "connecting to " + settings.brokerUrl());
        link.connect();
    }

    /** Publishes what the outbox lets go now, when connected. */
    void drain() {
        if (link == null || connectedGeneration != link.generation()) {
            return;
        }
        for (Message m : outbox.next()) {
            link.publish(m);
        }
    }

    @Override
    public void connected(int generation) {
        if (link == null || generation != link.generation()) {
            return;
        }
        connectedGeneration = generation;
        backoff = backoff.reset();
        linkWords = "connected to " + settings.brokerUrl();
        LOG.info("MQTT bridge connected to {} as {}", settings.brokerUrl(), settings.flatId());
        lastProblem = "";
        status.accept(DeviceStatus.State.ONLINE, linkWords);
        outbox.connected();
        drain();
        showFigures();
    }

    @Override
    public void failed(int generation, String why, boolean refused) {
        if (link == null || generation != link.generation()) {
            return;
        }
        offline(why, refused);
    }

    @Override
    public void lost(int generation, String why) {
        if (link == null || generation != link.generation()) {
            return;
        }
        offline("connection lost: " + why, false);
    }

    private void offline(String why, boolean refused) {
        connectedGeneration = -1;
        backoff = backoff.failed();
        long wait = backoff.delaySeconds();
        linkWords = why + "; trying again in " + wait + " s";
        if (!why.equals(lastProblem)) {
            lastProblem = why;
            LOG.warn("MQTT bridge: {}; trying again every {} s at most, alerts wait on disk", why, MAX_WAIT_SECONDS);
        }
        status.accept(refused ? DeviceStatus.State.ERROR : DeviceStatus.State.OFFLINE, linkWords);
        executor.schedule(Bridge.guard(link::connect), wait, TimeUnit.SECONDS);
        showFigures();
    }

    @Override
    public void published(int generation, Message m, boolean ok) {
        try {
            if (generation != connectedGeneration) {
                if (ok && m.spooled()) {
                    outbox.spool().delivered(m); // an answer of an earlier connection: still delivered
                }
                return;
            }
            outbox.done(m, ok);
        } catch (IOException e) {
            problem("the outbox " + settings.queueDir() + " cannot be updated: " + e.getMessage()
                    + " (the message may be sent again)");
        }
        drain();
    }

    @Override
    public void command(String topic, byte[] payload) {
        CommandGuard.Verdict v = guard.check(topic, payload);
        Commands.Result r = v.refusal() != null ? new Commands.Result(false, v.refusal())
                : commands.handle(topic, v.command());
        if (r.accepted()) {
            accepted++;
            LOG.info("MQTT command on {} carried out: {}", topic, r.reason());
        } else {
            rejected++;
            LOG.info("MQTT command on {} refused: {}", topic, r.reason());
        }
        outbox.transientMessage(commands.result(topic, r, clock.get()));
        drain();
        showFigures();
    }

    /** A problem of the bridge itself (the disk): ERROR with the reason, one log line. */
    void problem(String why) {
        LOG.warn("MQTT bridge: {}", why);
        status.accept(DeviceStatus.State.ERROR, why);
    }

    void showFigures() {
        figures.accept(new Figures(linkWords, outbox.waitingAlerts(), outbox.waitingState(), outbox.delivered(),
                accepted, rejected, guard.refused(), outbox.droppedTransient(), scan.devices()));
    }
}
