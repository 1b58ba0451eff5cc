package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.time.Instant;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.osgi.framework.BundleContext;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.device.DeviceStatus;

/**
 * The running bridge of one configuration. Everything happens on one executor thread ({@code tinysep-mqtt}):
 * reading state, the outbox, Paho's answers, commands. Nothing the platform calls waits for the broker: alert
 * changes and Paho callbacks are only queued here. Stopped by {@link #stop()} (orderly {@code offline}).
 */
final class Bridge implements Link.Events {

    private static final Logger LOG = LoggerFactory.getLogger(Bridge.class);
    private static final long DAY_SECONDS = 86_400;

    private final BundleContext context;
    private final Settings settings;
    private final Topics topics;
    private final Supplier<Instant> clock;
    private final BiConsumer<DeviceStatus.State, String> status;
    private final Consumer<Figures> figures;
    private final ScheduledExecutorService executor;
    private Outbox outbox;
    private Alerts alerts;
    private AlertFeed feed;
    private DeviceScan scan;
    private FlatState flat;
    private Commands commands;
    private Link link;
    private int connectedGeneration = -1;
    private int backoffSeconds = 1;
    private String lastProblem = "";
    private long accepted;
    private long rejected;
    private long lastSummary = Long.MIN_VALUE;
    private String linkWords = "connecting";

    Bridge(BundleContext context, Settings settings, Supplier<Instant> clock,
            BiConsumer<DeviceStatus.State, String> status, Consumer<Figures> figures) {
        this.context = context;
        this.settings = settings;
        this.topics = new Topics(settings.topicPrefix(), settings.flatId(), settings.discoveryPrefix());
        this.clock = clock;
        this.status = status;
        this.figures = figures;
        ScheduledThreadPoolExecutor ex = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, "tinysep-mqtt-" + settings.flatId());
            t.setDaemon(true);
            return t;
        });
        ex.setRemoveOnCancelPolicy(true);
        ex.setRejectedExecutionHandler(new java.util.concurrent.ThreadPoolExecutor.DiscardPolicy()); // late Paho answers after stop
        this.executor = ex;
    }

    void start() {
        executor.execute(this::init);
    }

    private void init() {
        try {
            outbox = new Outbox(new AlertSpool(settings.queueDir()), topics.status());
        } catch (IOException e) {
            String why = "the outbox folder " + settings.queueDir() + " cannot be used: " + e.getMessage();
            LOG.warn("MQTT bridge not started: {}", why);
            status.accept(DeviceStatus.State.ERROR, why);
            return;
        }
        alerts = new Alerts(topics, outbox);
        scan = new DeviceScan(context, topics, clock);
        flat = new FlatState(context, topics, clock, settings.heartbeatSeconds());
        feed = new AlertFeed(context, executor, this::alertChanged, this::alertServiceAdded);
        commands = new Commands(topics, scan, feed::service);
        outbox.state(Message.state(topics.status(), "online"));
        if (topics.discovery()) {
            Discovery d = new Discovery(topics);
            outbox.state(d.occupancy());
            for (AlertKind k : AlertKind.values()) {
                outbox.state(d.alertKind(k));
            }
        }
        try {
            link = new Link(settings, topics, executor, this);
        } catch (MqttException | RuntimeException e) {
            String why = "the MQTT client cannot be created for " + settings.brokerUrl() + ": " + Words.describe(e);
            LOG.warn("MQTT bridge not started: {}", why);
            status.accept(DeviceStatus.State.ERROR, why);
            return;
        }
        LOG.info("MQTT bridge started: {}", settings.redacted());
        status.accept(DeviceStatus.State.OFFLINE, "connecting to " + settings.brokerUrl());
        link.connect();
        executor.scheduleWithFixedDelay(guard(this::poll), 0, settings.pollSeconds(), TimeUnit.SECONDS);
        executor.scheduleWithFixedDelay(guard(this::heartbeat), 0, settings.heartbeatSeconds(), TimeUnit.SECONDS);
    }

    private Runnable guard(Runnable r) {
        return () -> {
            try {
                r.run();
            } catch (RuntimeException e) {
                LOG.warn("MQTT bridge: {} failed, it goes on: {}", r, Words.describe(e));
            }
        };
    }

    private void poll() {
        scan.poll(outbox::state);
        flat.poll(outbox::state, feed.service(), alerts);
        drain();
        showFigures();
    }

    private void heartbeat() {
        outbox.state(flat.platform());
        long now = clock.get().getEpochSecond();
        if (lastSummary == Long.MIN_VALUE || now - lastSummary >= DAY_SECONDS) {
            lastSummary = now;
            outbox.state(flat.summary(feed.service(), scan.devices(), scan.offline()));
        }
        drain();
    }

    private void alertServiceAdded(org.tinysep.api.alert.AlertService service) {
        try {
            alerts.sync(service);
        } catch (IOException e) {
            problem("alert messages cannot be written to the outbox " + settings.queueDir() + ": " + e.getMessage());
        }
        drain();
    }

    private void alertChanged(org.tinysep.api.alert.Alert a) {
        try {
            alerts.changed(a);
        } catch (IOException e) {
            problem("alert " + a.id() + " cannot be written to the outbox " + settings.queueDir() + ": "
                    + e.getMessage() + "; it is published when the disk works again");
        }
        drain();
    }

    private void drain() {
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
        backoffSeconds = 1;
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
        int wait = backoffSeconds;
        backoffSeconds = Math.min(30, backoffSeconds * 2);
        linkWords = why + "; trying again in " + wait + " s";
        if (!why.equals(lastProblem)) {
            lastProblem = why;
            LOG.warn("MQTT bridge: {}; trying again every {} s at most, alerts wait on disk", why, 30);
        }
        status.accept(refused ? DeviceStatus.State.ERROR : DeviceStatus.State.OFFLINE, linkWords);
        executor.schedule(guard(link::connect), wait, TimeUnit.SECONDS);
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
        Commands.Result r = commands.handle(topic, payload);
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

    private void problem(String why) {
        LOG.warn("MQTT bridge: {}", why);
        status.accept(DeviceStatus.State.ERROR, why);
    }

    private void showFigures() {
        figures.accept(new Figures(linkWords, outbox.waitingAlerts(), outbox.waitingState(), outbox.delivered(),
                accepted, rejected, outbox.droppedTransient(), scan.devices()));
    }

    /** Publishes {@code offline}, disconnects and stops the thread; waits at most a few seconds. */
    void stop() {
        try {
            executor.submit(() -> {
                if (link != null) {
                    link.close(2000);
                }
                if (feed != null) {
                    feed.close();
                }
                if (scan != null) {
                    scan.close();
                }
                if (flat != null) {
                    flat.close();
                }
            }).get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            LOG.warn("MQTT bridge: stopping took too long ({}); stopped anyway", Words.describe(e));
        } finally {
            executor.shutdownNow();
            try {
                executor.awaitTermination(5, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        LOG.info("MQTT bridge stopped");
    }
}
