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
 * reading state, the outbox, Paho's answers ({@link Session}), commands. Nothing the platform calls waits for the
 * broker: alert changes and Paho callbacks are only queued here. Stopped by {@link #stop()} (orderly {@code offline}).
 */
final class Bridge {

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
    private DriversState drivers;
    private Session session;
    private Link link;
    private long lastSummary = Long.MIN_VALUE;
    private final FlatKey key;
    private final Consumer<String> problem;

    /**
     * @param key     the flat's key (or why there is none), read at activation
     * @param problem records a PROBLEM in the event log
     */
    Bridge(BundleContext context, Settings settings, Supplier<Instant> clock,
            BiConsumer<DeviceStatus.State, String> status, Consumer<Figures> figures, FlatKey key,
            Consumer<String> problem) {
        this.key = key;
        this.problem = problem;
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
        drivers = DriversState.tracking(context, topics);
        feed = new AlertFeed(context, executor, this::alertChanged, this::alertServiceAdded);
        session = new Session(settings, executor, clock, status, figures, outbox,
                new Commands(topics, scan, feed::service),
                new CommandGuard(topics, settings, key.key(), key.missing(), java.time.Clock.systemUTC(), problem), scan);
        outbox.state(Message.state(topics.status(), "online"));
        if (topics.discovery()) {
            Discovery d = new Discovery(topics);
            outbox.state(d.occupancy());
            for (AlertKind k : AlertKind.values()) {
                outbox.state(d.alertKind(k));
            }
        }
        try {
            link = new Link(settings, topics, executor, session);
            link.signWith(key.key());
        } catch (MqttException | RuntimeException e) {
            String why = "the MQTT client cannot be created for " + settings.brokerUrl() + ": " + Trouble.describe(e);
            LOG.warn("MQTT bridge not started: {}", why);
            status.accept(DeviceStatus.State.ERROR, why);
            return;
        }
        LOG.info("MQTT bridge started: {}", settings.redacted());
        session.start(link);
        executor.scheduleWithFixedDelay(guard(this::poll), 0, settings.pollSeconds(), TimeUnit.SECONDS);
        executor.scheduleWithFixedDelay(guard(this::heartbeat), 0, settings.heartbeatSeconds(), TimeUnit.SECONDS);
    }

    /** @return the task, whose failure is logged in one line and does not stop the bridge's later runs */
    static Runnable guard(Runnable r) {
        return () -> {
            try {
                r.run();
            } catch (RuntimeException e) {
                LOG.warn("MQTT bridge: {} failed, it goes on: {}", r, Trouble.describe(e));
            }
        };
    }

    private void poll() {
        scan.poll(outbox::state);
        flat.poll(outbox::state, feed.service(), alerts);
        outbox.state(drivers.message());
        session.drain();
        session.showFigures();
    }

    private void heartbeat() {
        outbox.state(flat.platform());
        long now = clock.get().getEpochSecond();
        if (lastSummary == Long.MIN_VALUE || now - lastSummary >= DAY_SECONDS) {
            lastSummary = now;
            outbox.state(flat.summary(feed.service(), scan.devices(), scan.offline()));
        }
        session.drain();
    }

    private void alertServiceAdded(org.tinysep.api.alert.AlertService service) {
        try {
            alerts.sync(service);
        } catch (IOException e) {
            session.problem("alert messages cannot be written to the outbox " + settings.queueDir() + ": " + e.getMessage());
        }
        session.drain();
    }

    private void alertChanged(org.tinysep.api.alert.Alert a) {
        try {
            alerts.changed(a);
        } catch (IOException e) {
            session.problem("alert " + a.id() + " cannot be written to the outbox " + settings.queueDir() + ": "
                    + e.getMessage() + "; it is published when the disk works again");
        }
        session.drain();
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
                if (drivers != null) {
                    drivers.close();
                }
            }).get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            LOG.warn("MQTT bridge: stopping took too long ({}); stopped anyway", Trouble.describe(e));
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
