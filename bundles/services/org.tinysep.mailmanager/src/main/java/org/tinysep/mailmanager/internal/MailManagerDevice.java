package org.tinysep.mailmanager.internal;

import java.time.Clock;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;

/**
 * The Mail Manager device (thesis 4.4.3.3): created at once by its driver, it takes send requests from any device
 * ({@link MailProvider}) and hands them to its {@link Outbox}. The event log says, per message and in plain words,
 * queued, delivered, failed temporarily (retrying at), or not delivered (subject and recipients, never the body
 * or the password); its status ({@link MailHealth}) says where alerts go and shows an undelivered alert until a
 * delivery succeeds.
 */
final class MailManagerDevice extends WholeFlatDevice implements OutboxEvents {

    private static final Logger LOG = LoggerFactory.getLogger(MailManagerDevice.class);
    /**
     * The text of each mail that could not be sent, written to the console instead (logger {@value #MAIL_LOGGER},
     * WARN): the demo flat turns it down to ERROR so its console gets one line per alert; the
     * delivery itself is always in the event log.
     */
    static final String MAIL_LOGGER = "tinysep.mail";
    private static final Logger MAIL = LoggerFactory.getLogger(MAIL_LOGGER);

    private final Listeners<MailManagerListener> listeners;
    private final Outbox outbox;
    private final AtomicLong sent = new AtomicLong();
    private final MailProvider provider;
    private final Deliveries deliveries = new Deliveries();
    private volatile MailSettings settings;
    private volatile String configProblem;
    private volatile String lastProblem = "";
    private volatile String undelivered;
    private volatile String outboxDetail = "";
    private volatile Consumer<MailHealth> onHealth = h -> { };

    /** @param configProblem why the configuration was refused, or null */
    MailManagerDevice(DriverContext context, MailSettings settings, String configProblem, SmtpTransport transport) {
        this(context, settings, configProblem, transport, Clock.systemUTC(), null);
    }

    /**
     * @param wall     the computer's clock, for the give-up age
     * @param onHealth told (on the mail thread) whenever where alerts go or what is wrong changes; may be null
     */
    MailManagerDevice(DriverContext context, MailSettings settings, String configProblem, SmtpTransport transport,
            Clock wall, Consumer<MailHealth> onHealth) {
        super(context, Uids.of(context.driverName(), "device"), context.driverName(), "Mail Manager");
        this.listeners = new Listeners<>(uid());
        this.provider = new MailProvider(uid(), this::sendTo, this::mailStatus, listeners, deliveries,
                () -> this.settings.recipients());
        this.settings = settings;
        this.configProblem = configProblem;
        if (onHealth != null) {
            this.onHealth = onHealth;
        }
        publish(provider, MailManagerProvider.class);
        this.outbox = new Outbox(settings, transport, this, context::now, wall);
        showHealth(); // from the start: the outbox only reports changes, and "no SMTP host" may never change
    }

    /** Applies a changed configuration without replacing the device (its consumers stay connected). */
    void reconfigure(MailSettings next, String problem) {
        settings = next;
        configProblem = problem;
        outbox.reconfigure(next); // queued before anything sent once the properties below show the new settings
        showHealth(); // the outbox may stay in the same state (e.g. NOT_CONFIGURED for a refused and for no host)
    }

    private String sendTo(List<String> to, String subject, String body) {
        List<String> checked = MailSettings.addresses(to);
        return Long.toString(outbox.send(checked, subject, body));
    }

    /** @return the MailManagerProvider service object */
    MailManagerProvider provider() {
        return provider;
    }

    MailStatus mailStatus() {
        MailStatus s = outbox.status();
        return s == null ? (settings.configured() ? MailStatus.IDLE : MailStatus.NOT_CONFIGURED) : s;
    }

    /** @return where alerts go and what is wrong, now */
    MailHealth health() {
        return new MailHealth(settings, configProblem, mailStatus(), outboxDetail, undelivered);
    }

    @Override
    public void statusChanged(MailStatus s, String detail) {
        outboxDetail = detail == null ? "" : detail;
        if (s == MailStatus.RETRYING) {
            lastProblem = detail;
        }
        showHealth();
        listeners.fire(l -> l.mailStatusChanged(provider, s, now()));
    }

    @Override
    public void undelivered(String notice) {
        if (!Objects.equals(notice, undelivered)) {
            undelivered = notice;
            showHealth();
        }
    }

    private synchronized void showHealth() {
        MailHealth h = health();
        status(h.state(), h.statusDetail());
        onHealth.accept(h);
    }

    @Override
    public void queued(MailMessage m, List<String> recipients) {
        deliveries.update(m, recipients, MailDelivery.Outcome.QUEUED, "queued for " + String.join(", ", recipients),
                now());
        event(MailText.mail(m) + " queued for " + String.join(", ", recipients));
    }

    @Override
    public void delivered(MailMessage m, List<String> recipients) {
        sent.incrementAndGet();
        deliveries.update(m, recipients, MailDelivery.Outcome.SENT, "delivered to " + String.join(", ", recipients),
                now());
        event(MailText.mail(m) + " delivered to " + String.join(", ", recipients));
    }

    @Override
    public void retrying(MailMessage m, String what) {
        deliveries.update(m, m.to(), MailDelivery.Outcome.RETRYING, what, now());
        event(what);
    }

    @Override
    public void failed(MailMessage m, String what) {
        deliveries.update(m, m.to(), MailDelivery.Outcome.FAILED, what, now());
        LOG.warn("Mail Manager: {}", what);
        problem(what);
    }

    @Override
    public void warning(String message) {
        LOG.warn("Mail Manager: {}", message);
        problem(message);
    }

    @Override
    public void logged(MailMessage m) {
        deliveries.update(m, m.to(), MailDelivery.Outcome.LOGGED_ONLY, "NOT mailed, only written to the log ("
                + (configProblem == null ? MailHealth.NO_HOST : "bad configuration: " + configProblem) + ")", now());
        MAIL.warn("Mail Manager {}: mail not sent, written here instead. Subject: {}\n{}",
                configProblem == null ? "has no SMTP host" : "is misconfigured", m.subject(), m.body());
        event(MailText.mail(m) + " NOT mailed, only written to the log ("
                + (configProblem == null ? MailHealth.NO_HOST : "bad configuration: " + configProblem) + ")");
    }

    @Override
    public void problem(String message) {
        lastProblem = message;
        context.reporter().event(EventKind.PROBLEM, uid(), message);
    }

    @Override
    protected List<Parameter> moreParameters() {
        List<Parameter> all = new ArrayList<>(List.of(
                Parameter.readOnly("delivery", health().summary(), "where alerts go, in plain words"),
                Parameter.readOnly("mailStatus", mailStatus(), "IDLE, SENDING, RETRYING or NOT_CONFIGURED"),
                Parameter.readOnly("undelivered", undelivered == null ? "" : undelivered,
                        "the last alert that could not be delivered, until a delivery succeeds"),
                Parameter.readOnly("queued", outbox.queued(), "messages waiting in the spool"),
                Parameter.readOnly("sent", sent.get(), "messages sent since start"),
                Parameter.readOnly("lastProblem", lastProblem, "the last failure, if any")));
        all.addAll(SettingsParameters.of(settings));
        return all;
    }

    @Override
    public List<DeviceFunction> functions() {
        return List.of(new DeviceFunction("retryNow", "skip the back-off delay and try the queued mail now"));
    }

    @Override
    public String invoke(String function) {
        if (!"retryNow".equals(function)) {
            return super.invoke(function);
        }
        outbox.retryNow();
        return "retrying " + outbox.queued() + " queued message(s) now";
    }

    @Override
    protected void onDispose() {
        outbox.close();
        listeners.closeAll();
    }
}
