package org.tinysep.sms.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.util.Optional;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.channel.ReplyHandler;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.device.support.files.StateFolder;

/**
 * The SMS channel (README): alerts go out as SMS through gammu-smsd's files spool ({@link Spool}), replies that
 * arrive in its inbox go to the {@link ReplyHandler} (the alert service) and its answer goes back by SMS. When
 * gammu-smsd is not running or the modem does not send, the channel is in ERROR in plain words and {@link #send}
 * fails at once, so the alert service tries the contact's next channel. The modem is a device of the platform
 * with the same state ({@link ModemDevice}). The inbox is watched ({@link InboxWatch}): a reply is read as it
 * arrives; the modem's state is looked at every {@code pollMillis} while an SMS waits in the outbox (or the inbox
 * cannot be watched), otherwise every {@code idleSeconds}, so an idle channel does not wake every second.
 */
@Component(service = MessageChannel.class, configurationPid = "org.tinysep.sms", immediate = true,
        property = MessageChannel.SCHEME + "=sms")
@Designate(ocd = SmsConfig.class)
public final class SmsChannel implements MessageChannel {

    static final String ORIGIN = "SMS";
    private static final Logger LOG = LoggerFactory.getLogger(SmsChannel.class);

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile EventLog eventLog;
    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile ReplyHandler replies;

    private ScheduledExecutorService poller;
    private InboxWatch inbox;
    private long pollMillis;
    private long idleMillis;
    private final AtomicLong looks = new AtomicLong();
    private final AtomicBoolean replyLookPending = new AtomicBoolean();
    /** How long after a file appears in the inbox it is read: gammu-smsd writes it in that time. */
    static final long REPLY_SETTLE_MILLIS = 200;
    /** The modem as a device of the platform ({@link ModemDevice}); null without OSGi (unit tests). */
    private ModemDriver modem;
    private ModemHealth health;
    private Spool spool;
    private int maxParts;
    private volatile DeviceStatus said;
    /** Whether anything was sent: an SMS channel nobody set up or used stays quiet in the log. */
    private volatile boolean used;

    @Activate
    void activate(BundleContext context, SmsConfig c) {
        Path base = StateFolder.resolveOrDataArea(c.spoolFolder(), context, "sms");
        this.modem = new ModemDriver(context, base, c.pidFile(), c.stuckSeconds());
        start(base, c.pidFile(), c.stuckSeconds(), c.maxParts(), c.pollMillis(), c.idleSeconds() * 1000L);
    }

    /** The activation without OSGi (tests), looking every minute when idle. */
    void start(Path base, String pidFile, int stuckSeconds, int parts, int pollMillis) {
        start(base, pidFile, stuckSeconds, parts, pollMillis, 60_000);
    }

    /** The activation without OSGi (tests). */
    void start(Path base, String pidFile, int stuckSeconds, int parts, int pollMillis, long idleMillis) {
        this.spool = new Spool(base);
        this.maxParts = Math.max(1, Math.min(3, parts));
        this.health = new ModemHealth(spool, pidFile, Math.max(1, stuckSeconds), Clock.systemUTC());
        this.pollMillis = Math.max(100, pollMillis);
        this.idleMillis = Math.max(this.pollMillis, idleMillis);
        this.poller = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "tinysep-sms"));
        this.inbox = new InboxWatch(this::lookNow);
        poller.execute(this::look);
    }

    /**
     * A file arrived in the inbox: look shortly (on the poller's thread, so looks never overlap), once gammu-smsd
     * has had time to finish writing it; a burst of events is one look when they come within that time.
     */
    private void lookNow() {
        if (!replyLookPending.compareAndSet(false, true)) {
            return;
        }
        try {
            poller.schedule(() -> {
                replyLookPending.set(false);
                poll();
            }, REPLY_SETTLE_MILLIS, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException e) {
            // deactivated
        }
    }

    /** A scheduled look; the next one comes soon while something is pending, else after {@code idleSeconds}. */
    private void look() {
        poll();
        boolean watched = inbox.watch(spool.folder("inbox"));
        boolean setUp = used || Files.isDirectory(spool.base()); // else: nothing to watch for
        long next = setUp && (!watched || spool.outboxWaiting()) ? pollMillis : idleMillis;
        try {
            poller.schedule(this::look, next, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException e) {
            // deactivated
        }
    }

    /** @return how many times the state and the inbox were looked at (for tests: wake-ups when idle) */
    long looks() {
        return looks.get();
    }

    /** For tests: who hears replies. */
    void use(ReplyHandler h) {
        replies = h;
    }

    @Deactivate
    void deactivate() {
        inbox.close();
        poller.shutdownNow();
        try {
            poller.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (modem != null) {
            modem.close();
        }
    }

    @Override
    public String scheme() {
        return "sms";
    }

    @Override
    public String name() {
        return "SMS through the GSM modem (gammu-smsd)";
    }

    @Override
    public DeviceStatus status() {
        return health.status();
    }

    @Override
    public ChannelDelivery send(String address, ChannelMessage m) {
        used = true;
        DeviceStatus s = status();
        if (s.state() == DeviceStatus.State.ERROR) {
            return ChannelDelivery.failed(s.detail());
        }
        return queue(address, SmsText.fit(m.title(), m.text(), maxParts));
    }

    private ChannelDelivery queue(String number, String text) {
        try {
            String id = spool.queue(number, text, Instant.now());
            return new ChannelDelivery(id, MailDelivery.Outcome.QUEUED, SmsText.parts(text) + " SMS to " + number
                    + " handed to gammu-smsd (" + (SmsText.gsm(text) ? "GSM 7-bit" : "UCS-2") + ")");
        } catch (IOException | RuntimeException e) {
            return ChannelDelivery.failed("the SMS could not be written to gammu-smsd's outbox " + spool.folder(
                    "outbox") + ": " + e);
        }
    }

    @Override
    public Optional<ChannelDelivery> delivery(String id) {
        return Optional.of(switch (spool.where(id)) {
            case SENT -> new ChannelDelivery(id, MailDelivery.Outcome.SENT, "sent by the GSM modem");
            case ERROR -> new ChannelDelivery(id, MailDelivery.Outcome.FAILED, "gammu-smsd could not send it (the "
                    + "network refused it or the number is wrong; its log says why)");
            case OUTBOX -> new ChannelDelivery(id, MailDelivery.Outcome.QUEUED, "waiting in gammu-smsd's outbox"
                    + (status().state() == DeviceStatus.State.ERROR ? ": " + status().detail() : ""));
            case GONE -> new ChannelDelivery(id, MailDelivery.Outcome.UNKNOWN, "no longer in gammu-smsd's folders");
        });
    }

    /** Every poll: the modem's state (logged when it changes) and the replies received. */
    private void poll() {
        looks.incrementAndGet();
        try {
            DeviceStatus now = health.status();
            DeviceStatus before = said;
            if (!used && !Files.isDirectory(spool.base())) {
                return; // not set up and not used: nothing to say, no inbox to read, no modem device
            }
            if (modem != null) {
                modem.show(now);
            }
            if (before == null || before.state() != now.state() || !before.detail().equals(now.detail())) {
                said = now;
                if (now.state() == DeviceStatus.State.ERROR) {
                    problem("SMS channel in ERROR: " + now.detail());
                } else if (before != null) {
                    event("SMS channel working again: " + now.detail());
                }
            }
            ReplyHandler h = replies;
            if (h != null && spool.missing().isEmpty()) {
                for (Spool.Incoming in : spool.incoming()) {
                    handle(h, in);
                }
            }
        } catch (IOException | RuntimeException e) {
            LOG.warn("SMS: reading gammu-smsd's inbox failed: {}", e.toString());
        }
    }

    private void handle(ReplyHandler h, Spool.Incoming in) throws IOException {
        spool.handled(in); // first, so that a reply is never acted on twice
        String said = in.text().strip().replaceAll("\\s+", " ");
        event("SMS received from " + in.from() + ": '" + (said.length() > 60 ? said.substring(0, 60) + "..." : said)
                + "'");
        Optional<String> answer = h.reply("sms", in.from(), in.text());
        if (answer.isPresent()) {
            ChannelDelivery d = queue(in.from(), SmsText.fit(answer.get(), "", maxParts));
            event("answer to " + in.from() + ": '" + answer.get() + "' (" + d.detail() + ")");
        }
    }

    private void event(String text) {
        LOG.info("SMS: {}", text);
        EventLog l = eventLog;
        if (l != null) {
            l.record(EventKind.DEVICE_EVENT, ORIGIN, text);
        }
    }

    private void problem(String text) {
        LOG.warn("SMS: {}", text);
        EventLog l = eventLog;
        if (l != null) {
            l.record(EventKind.PROBLEM, ORIGIN, text);
        }
    }
}
