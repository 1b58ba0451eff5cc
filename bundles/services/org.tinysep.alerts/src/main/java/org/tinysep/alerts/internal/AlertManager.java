package org.tinysep.alerts.internal;

import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertListener;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.channel.ReplyHandler;
import org.tinysep.api.device.Connection;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.device.support.files.StateFolder;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.device.support.time.PlatformTicker;

/**
 * The alert service (README): raises, keeps, repeats, escalates, acknowledges and clears alerts. Every change is
 * saved ({@link AlertBook}) before listeners hear of it, and is an event-log entry. Time is the platform's (the
 * Time Controller's, virtual time included): one {@link PlatformTicker} tick per second drives the schedule
 * ({@link Escalation}), the delivery outcomes ({@link Notifier#refresh}) and the daily summary.
 */
@Component(service = {AlertService.class, ReplyHandler.class}, configurationPid = "org.tinysep.alerts", immediate = true)
@Designate(ocd = AlertsConfig.class)
public final class AlertManager implements AlertService, ReplyHandler {

    private final FanOut fanOut = new FanOut();
    private final AlertLog log = new AlertLog();
    private PlatformClock clock;
    private AlertBook book;
    private Notifier notifier;
    private DailySummary summary;
    private volatile PlatformTicker ticker;
    private volatile MailManagerProvider mail;
    /** The SMS and push channels, by DS field injection. */
    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile List<MessageChannel> channels;
    private PhoneReplies replies;

    @Activate
    synchronized void activate(BundleContext context, AlertsConfig config) {
        AlertSettings s;
        String problem = null;
        try {
            s = AlertSettings.parse(config);
        } catch (IllegalArgumentException e) {
            s = AlertSettings.DEFAULTS;
            problem = "bad configuration of org.tinysep.alerts (" + e.getMessage() + "): using the defaults";
        }
        Path file = StateFolder.resolveOrDataArea(config.stateFile(), context, "alerts/alerts.properties");
        this.clock = PlatformClock.tracking(context);
        this.book = new AlertBook(new AlertStore(file), log::problem);
        ContactBook contacts = problem == null ? ContactBook.parse(config.contacts()) : ContactBook.EMPTY;
        this.notifier = new Notifier(s, contacts, this::channel, new AlertText(s.zone()), () -> mail, log::event,
                log::problem);
        this.replies = new PhoneReplies(contacts, this, log::event, log::problem);
        this.summary = new DailySummary(context, s, StateFolder.resolve(null, context, "").orElse(file.getParent()),
                log::signals);
        if (problem != null) {
            log.problem(problem);
        }
        book.load();
        book.restored().ifPresent(log::event);
        summary.start(book, clock.now());
        this.ticker = PlatformTicker.whenDue(context, "tinysep-alerts", this::tick);
    }

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    void bindEventLog(EventLog e) {
        log.use(e);
    }

    void unbindEventLog(EventLog e) {
        log.gone(e);
    }

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    void bindMail(MailManagerProvider m) {
        mail = m;
    }

    void unbindMail(MailManagerProvider m) {
        if (mail == m) {
            mail = null;
        }
    }

    @Override
    public Alert raise(AlertRequest r) {
        Alert a;
        synchronized (this) {
            Optional<Alert> same = book.open().stream().filter(x -> x.source().equals(r.source())
                    && x.raisedAt().equals(r.raisedAt())).findFirst();
            if (same.isPresent()) {
                return same.get();
            }
            a = Copies.raised(book.nextId(), r);
            log.raised("alert " + a.id() + " raised (" + a.kind().name().toLowerCase() + "): " + a.subject());
            book.put(a);
            a = advance(a, clock.now());
        }
        changed(a);
        return a;
    }

    @Override
    public Alert acknowledge(String id, String by) {
        if (by == null || by.isBlank()) {
            throw new IllegalArgumentException("say who acknowledges alert " + id + " (a name)");
        }
        Alert done;
        synchronized (this) {
            Alert a = book.get(id).orElseThrow(() -> new IllegalArgumentException("there is no alert " + id
                    + " (tinysep:alerts lists them)"));
            if (!a.isOpen()) {
                throw new IllegalStateException("alert " + a.id() + " is not open: " + a.state().name()
                        .toLowerCase() + " at " + notifier.words().fullTime(a.closedAt()) + " (" + a.closedBy() + ")");
            }
            Instant now = clock.now();
            done = Copies.closed(a, AlertState.ACKNOWLEDGED, now, by.strip());
            book.put(done);
            log.event("alert " + a.id() + " acknowledged by " + by.strip() + " at " + notifier.words().time(now)
                    + ": it is not repeated or passed on any more (" + a.subject() + ")");
        }
        changed(done);
        return done;
    }

    @Override
    public List<Alert> clear(String source, String why) {
        List<Alert> cleared = new ArrayList<>();
        synchronized (this) {
            Instant now = clock.now();
            for (Alert a : book.all()) {
                if (!a.source().equals(source) || a.state() == AlertState.CLEARED) {
                    continue;
                }
                boolean wasOpen = a.isOpen();
                Alert c = Copies.closed(a, AlertState.CLEARED, now, why);
                c = wasOpen ? notifier.allClear(c, why, now) : c;
                book.put(c);
                boolean queued = c.notifications().size() > a.notifications().size();
                log.event("alert " + a.id() + " cleared: " + why + (!wasOpen ? " (it was acknowledged; no all clear "
                        + "sent)" : queued ? "; all clear queued to the Mail Manager for " + AlertText.who(notifier
                        .toldSoFar(c)) + Notifier.QUEUED_NOTE : ""));
                cleared.add(c);
            }
        }
        cleared.forEach(this::changed);
        return cleared;
    }

    /** A reply from a phone: see {@link PhoneReplies}. */
    @Override
    public Optional<String> reply(String scheme, String from, String text) {
        return replies.reply(scheme, from, text);
    }

    private MessageChannel channel(String scheme) {
        List<MessageChannel> all = channels;
        return all == null ? null : all.stream().filter(c -> scheme.equals(c.scheme())).findFirst().orElse(null);
    }

    @Override
    public synchronized List<Alert> open() {
        return book.open();
    }

    @Override
    public synchronized List<Alert> recent(int max) {
        List<Alert> all = new ArrayList<>(book.all());
        all.sort(Comparator.comparingLong(a -> Long.parseLong(a.id())));
        return all.subList(Math.max(0, all.size() - Math.max(0, max)), all.size());
    }

    @Override
    public synchronized Optional<Alert> alert(String id) {
        return book.get(id);
    }

    @Override
    public Connection connect(AlertListener listener) {
        return fanOut.add(listener);
    }

    /**
     * A platform tick when due: messages due, delivery outcomes, the daily summary.
     *
     * @return when it is next due: every tick while an alert is open or one of its messages is not finished (its
     *         repeats, escalations and delivery outcomes), else when the next daily summary is due (null: none)
     */
    Instant tick(Instant now) {
        List<Alert> changed = new ArrayList<>();
        Instant due;
        synchronized (this) {
            for (Alert a : book.all()) {
                Alert next = notifier.refresh(advance(a, now), now);
                if (!next.equals(a)) {
                    book.put(next);
                    changed.add(next);
                }
            }
            summary.tick(book, now, notifier);
            due = nextDue(book.all(), notifier.settings(), book.lastSummary(), now);
        }
        changed.forEach(this::changed);
        return due;
    }

    /**
     * @return {@code now} (every tick) while an alert is open or one of its messages is not finished, else when the
     *         next daily summary is due (null: no summary)
     */
    static Instant nextDue(List<Alert> all, AlertSettings s, java.time.LocalDate lastSummary, Instant now) {
        return all.stream().anyMatch(a -> a.isOpen() || DeliveryWatch.waiting(a)) ? now
                : DailySummary.nextDue(s, lastSummary, now);
    }

    /** Sends the message due for {@code a} now, if any; the caller holds the lock and saves. */
    private Alert advance(Alert a, Instant now) {
        Optional<Escalation.Step> step = Escalation.due(a, notifier.settings(), now);
        if (step.isEmpty()) {
            return a;
        }
        Alert next = notifier.send(a, step.get(), now);
        if (next != a) {
            book.put(next);
        }
        return next;
    }

    private void changed(Alert a) {
        PlatformTicker t = ticker;
        if (t != null) {
            t.wakeNext(); // raised, acknowledged or cleared: its messages are watched from the next tick
        }
        fanOut.changed(a);
    }

    @Deactivate
    synchronized void deactivate() {
        ticker.close();
        summary.close();
        clock.close();
        fanOut.close();
    }
}
