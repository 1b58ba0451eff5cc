package org.tinysep.alerts.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.device.support.files.AtomicFiles;
import org.tinysep.device.support.files.StateFolder;

/**
 * Turns the event log's "monitoring reduced" and "node type mismatch" {@code PROBLEM} entries into a notice mail
 * to the caregivers (the Mail Manager's recipients), once per cause. A notice is not an
 * alert: it is neither repeated nor escalated. The log is read every {@value #PERIOD_SECONDS} s; the last entry
 * handled is saved ({@code notices.properties} next to the alerts), so a restart neither repeats nor loses one.
 * Without a Mail Manager the signals wait and go out when one appears. A signal about one sensor that went away waits
 * {@code noticeGraceSeconds} first and is dropped when the sensor is back by then ({@link NoticeGrace}), so a
 * platform start does not mail "monitoring reduced" notices.
 */
@Component(service = {}, immediate = true, configurationPid = "org.tinysep.alerts")
public final class MonitoringNotices {

    static final int PERIOD_SECONDS = 2;
    private static final Duration QUIET = Duration.ofMinutes(30);
    private static final Logger LOG = LoggerFactory.getLogger(MonitoringNotices.class);

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile EventLog eventLog;
    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile MailManagerProvider mail;
    private NoticeFeed feed;
    private NoticeText text;
    private Path file;
    private NoticeGrace grace = new NoticeGrace(Duration.ZERO);
    private Supplier<Instant> clock = Instant::now;
    private ScheduledExecutorService executor;

    public MonitoringNotices() {
    }

    /** Test seam: a component with its feed, words and file, without executor. */
    MonitoringNotices(NoticeFeed feed, NoticeText text, Path file) {
        this.feed = feed;
        this.text = text;
        this.file = file;
    }

    /** Test seam: with a grace for sensor notices and the clock it is measured on. */
    MonitoringNotices(NoticeFeed feed, NoticeText text, Path file, Duration grace, Supplier<Instant> clock) {
        this(feed, text, file);
        this.grace = new NoticeGrace(grace);
        this.clock = clock;
    }

    @Activate
    void activate(BundleContext context, AlertsConfig config) {
        ZoneId zone;
        try {
            zone = config.timeZone().isBlank() ? ZoneId.systemDefault() : ZoneId.of(config.timeZone().strip());
        } catch (RuntimeException e) {
            zone = ZoneId.systemDefault(); // the alert service reports the bad setting
        }
        this.text = new NoticeText(zone);
        this.file = StateFolder.resolveOrDataArea(config.stateFile(), context, "alerts/alerts.properties")
                .resolveSibling("notices.properties");
        this.feed = new NoticeFeed(load(file), QUIET);
        this.grace = new NoticeGrace(Duration.ofSeconds(Math.max(0, config.noticeGraceSeconds())));
        this.executor = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "tinysep-notices"));
        executor.scheduleWithFixedDelay(this::pollSafely, 0, PERIOD_SECONDS, TimeUnit.SECONDS);
    }

    @Deactivate
    void deactivate() {
        executor.shutdownNow();
    }

    private void pollSafely() {
        try {
            poll(eventLog, mail);
        } catch (RuntimeException e) { // the next poll tries again
            LOG.warn("Notices: could not read the event log or queue a notice: {}", e.toString());
        }
    }

    /** One look at the log: the new signals, mailed as one notice. Package-private for tests. */
    synchronized void poll(EventLog log, MailManagerProvider m) {
        if (log == null || m == null) {
            return; // without a Mail Manager the signals wait (nothing is marked handled)
        }
        List<EventEntry> newest = log.recent(1);
        if (grace.held() == 0 && !newest.isEmpty() && newest.get(0).sequence() == feed.last()) {
            return; // nothing new and no notice waiting for its grace: the log's last 500 entries are not copied
        }
        List<EventEntry> recent = log.recent(500);
        if (!feed.covers(recent)) {
            recent = log.recent(Integer.MAX_VALUE);
        }
        long before = feed.last();
        List<EventEntry> fresh = recent.stream().filter(e -> e.sequence() > before).toList();
        int dropped = grace.dropped();
        List<EventEntry> signals = grace.pass(feed.take(recent), fresh, clock.get());
        if (grace.dropped() != dropped) {
            LOG.info("Notices: {} sensor notice(s) not sent: the sensor was back within the grace",
                    grace.dropped() - dropped);
        }
        if (!signals.isEmpty()) {
            m.send(text.subject(signals), text.body(signals));
            log.record(EventKind.DEVICE_EVENT, AlertLog.ORIGIN, "notice sent to the caregivers ("
                    + signals.size() + " cause(s)): " + text.subject(signals));
        }
        if (feed.last() != before) {
            save(file, feed.last());
        }
    }

    NoticeFeed feed() {
        return feed;
    }

    static long load(Path file) {
        try {
            String s = Files.readString(file, StandardCharsets.UTF_8).strip();
            return s.startsWith("last=") ? Long.parseLong(s.substring(5).strip()) : 0;
        } catch (IOException | NumberFormatException e) {
            return 0; // none yet (or damaged): every signal in the log is noticed
        }
    }

    private static void save(Path file, long last) {
        try {
            AtomicFiles.createPrivateDirectories(file.getParent());
            AtomicFiles.write(file, ("last=" + last + "\n").getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            LOG.warn("Notices: could not save {} ({}); after a restart a notice may be sent again", file,
                    e.toString());
        }
    }
}
