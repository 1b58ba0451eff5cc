package org.tinysep.mailmanager.internal;

import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;

/**
 * The Mail Manager device (thesis 4.4.3.3): created at once by its driver, it takes {@link #send} requests from
 * any device and hands them to its {@link Outbox}. The event log gets one entry per message queued, sent or given
 * up on (subject only); the password never appears in a log, a status or a parameter. The provider is a separate
 * object because {@code MailManagerProvider.status()} and {@code Device.status()} differ in type.
 */
final class MailManagerDevice extends AbstractDevice implements OutboxEvents {

    private static final Logger LOG = LoggerFactory.getLogger(MailManagerDevice.class);

    private final Listeners<MailManagerListener> listeners;
    private final Outbox outbox;
    private final AtomicLong sent = new AtomicLong();
    private final MailProvider provider = new MailProvider();
    private volatile MailSettings settings;
    private volatile String configProblem;
    private volatile String lastProblem = "";

    /** @param configProblem why the configuration was refused, or null */
    MailManagerDevice(DriverContext context, MailSettings settings, String configProblem, SmtpTransport transport) {
        super(context, Uids.of(context.driverName(), "device"), context.driverName(), "Mail Manager");
        this.listeners = new Listeners<>(uid());
        this.settings = settings;
        this.configProblem = configProblem;
        publish(provider, MailManagerProvider.class);
        this.outbox = new Outbox(settings, transport, this, context::now);
    }

    /** Applies a changed configuration without replacing the device (its consumers stay connected). */
    void reconfigure(MailSettings next, String problem) {
        settings = next;
        configProblem = problem;
        outbox.reconfigure(next);
    }

    /** @return the MailManagerProvider service object */
    MailManagerProvider provider() {
        return provider;
    }

    MailStatus mailStatus() {
        MailStatus s = outbox.status();
        return s == null ? (settings.configured() ? MailStatus.IDLE : MailStatus.NOT_CONFIGURED) : s;
    }

    @Override
    public void statusChanged(MailStatus s, String detail) {
        if (configProblem != null) {
            status(DeviceStatus.State.ERROR, "bad configuration: " + configProblem
                    + "; mail is written to the log until it is fixed");
        } else if (s == MailStatus.NOT_CONFIGURED) {
            status(DeviceStatus.State.UNKNOWN, "no SMTP host configured: mail is written to the log");
        } else if (s == MailStatus.RETRYING) {
            lastProblem = detail;
            status(DeviceStatus.State.OFFLINE, detail);
        } else {
            status(DeviceStatus.State.ONLINE, s == MailStatus.IDLE ? "" : detail);
        }
        listeners.fire(l -> l.mailStatusChanged(provider, s, now()));
    }

    @Override
    public void queued(MailMessage m) {
        event("mail queued: \"" + m.subject() + "\"");
    }

    @Override
    public void sent(MailMessage m, String detail) {
        sent.incrementAndGet();
        event("mail sent: \"" + m.subject() + "\" (" + detail + ")");
    }

    @Override
    public void givenUp(MailMessage m, String reason) {
        problem("mail given up: \"" + m.subject() + "\": " + reason);
    }

    @Override
    public void logged(MailMessage m) {
        LOG.warn("Mail Manager {}: mail not sent, written here instead. Subject: {}\n{}",
                configProblem == null ? "has no SMTP host" : "is misconfigured", m.subject(), m.body());
        event("mail written to the log, not sent (" + (configProblem == null ? "no SMTP host" : "bad configuration")
                + "): \"" + m.subject() + "\"");
    }

    @Override
    public void problem(String message) {
        lastProblem = message;
        context.reporter().event(EventKind.PROBLEM, uid(), message);
    }

    @Override
    protected List<Parameter> moreParameters() {
        MailSettings s = settings;
        String cfg = "set through ConfigAdmin pid " + MailManagerDriver.PID;
        return List.of(
                Parameter.readOnly("mailStatus", mailStatus(), "IDLE, SENDING, RETRYING or NOT_CONFIGURED"),
                Parameter.readOnly("queued", outbox.queued(), "messages waiting in the spool"),
                Parameter.readOnly("sent", sent.get(), "messages sent since start"),
                Parameter.readOnly("lastProblem", lastProblem, "the last failure, if any"),
                Parameter.readOnly("host", s.host(), cfg),
                Parameter.readOnly("port", s.port(), cfg),
                Parameter.readOnly("security", s.security(), cfg),
                Parameter.readOnly("user", s.user(), cfg),
                Parameter.readOnly("password", s.password().isEmpty() ? "" : MailSettings.MASK, cfg),
                Parameter.readOnly("from", s.from(), cfg),
                Parameter.readOnly("recipients", String.join(", ", s.recipients()), cfg),
                Parameter.readOnly("spoolDir", s.spoolDir(), cfg));
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

    /** The MailManagerProvider side of the device. */
    private final class MailProvider implements MailManagerProvider {

        @Override
        public void send(String subject, String body) {
            outbox.send(subject, body);
        }

        @Override
        public MailStatus status() {
            return mailStatus();
        }

        @Override
        public String deviceUid() {
            return uid();
        }

        @Override
        public Connection connect(MailManagerListener listener) {
            return listeners.add(listener);
        }

        @Override
        public String toString() {
            return "MailManagerProvider of " + uid();
        }
    }

    /** A whole-flat service: it has no room. */
    @Override
    protected boolean placeable() {
        return false;
    }
}
