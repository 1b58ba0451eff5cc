package org.tinysep.push.internal;

import java.time.Instant;
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
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.device.support.files.StateFolder;

/**
 * The push channel (README): a contact's {@code push:topic} address is an ntfy topic; each message is one HTTPS
 * publish ({@link NtfyClient}) on the channel's own threads ({@link PushSender}): {@link #send} answers QUEUED at
 * once and {@link #delivery} says later whether the server took it. The status says whether the last message was
 * taken, and why not in words.
 */
@Component(service = MessageChannel.class, configurationPid = "org.tinysep.push", immediate = true,
        property = MessageChannel.SCHEME + "=push")
@Designate(ocd = PushConfig.class)
public final class PushChannel implements MessageChannel {

    private static final Logger LOG = LoggerFactory.getLogger(PushChannel.class);
    /** Publishes at once: a hanging server holds one thread, the next contact's push takes another. */
    private static final int THREADS = 4;

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile EventLog eventLog;
    private PushSettings settings;
    private PushSender sender;
    private volatile DeviceStatus status;

    @Activate
    void activate(BundleContext context, PushConfig c) {
        start(PushSettings.parse(c, StateFolder.resolveOrDataArea("", context, "secrets/push.token")));
    }

    /** The activation without OSGi (tests). */
    void start(PushSettings s) {
        stop();
        this.settings = s;
        this.sender = new PushSender(THREADS, this::outcome);
        this.status = s.server() == null ? new DeviceStatus(DeviceStatus.State.ERROR, s.problem() + "; alerts go "
                + "by the other channels", Instant.now()) : new DeviceStatus(DeviceStatus.State.UNKNOWN,
                        "nothing published to " + s.server().getHost() + " yet", Instant.now());
        String warning = PushToken.warning(s.tokenFile());
        if (!warning.isEmpty()) {
            record(EventKind.PROBLEM, warning);
        }
    }

    @Deactivate
    void stop() {
        PushSender s = sender;
        sender = null;
        if (s != null) {
            s.close();
        }
    }

    @Override
    public String scheme() {
        return "push";
    }

    @Override
    public String name() {
        return "push notification (ntfy)";
    }

    @Override
    public DeviceStatus status() {
        return status;
    }

    /** @return QUEUED at once (the publish runs on the channel's threads), or FAILED without a usable server */
    @Override
    public ChannelDelivery send(String topic, ChannelMessage m) {
        PushSettings s = settings;
        if (s.server() == null) {
            return ChannelDelivery.failed(s.problem());
        }
        return sender.submit("waiting for the answer of the push server " + s.server().getHost() + " (at most "
                + 2 * s.timeoutSeconds() + " s)", () -> NtfyClient.publish(s, topic, m));
    }

    @Override
    public Optional<ChannelDelivery> delivery(String id) {
        PushSender s = sender;
        return s == null ? Optional.empty() : s.delivery(id);
    }

    /** A message's outcome (on a push thread): the status follows; a change is an event-log entry. */
    private synchronized void outcome(ChannelDelivery d) {
        boolean ok = d.outcome() != MailDelivery.Outcome.FAILED;
        DeviceStatus before = status;
        status = new DeviceStatus(ok ? DeviceStatus.State.ONLINE : DeviceStatus.State.ERROR, ok ? "last message "
                + d.detail() : d.detail() + "; alerts go by the other channels", Instant.now());
        if (before.state() != status.state()) {
            record(ok ? EventKind.DEVICE_EVENT : EventKind.PROBLEM, "push channel " + (ok ? "working: " : "in ERROR: ")
                    + status.detail());
        }
    }

    private void record(EventKind kind, String text) {
        LOG.info("Push: {}", text);
        EventLog l = eventLog;
        if (l != null) {
            l.record(kind, "Push", text);
        }
    }
}
