package org.tinysep.push.internal;

import java.time.Instant;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
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
import org.tinysep.device.support.StateFolder;

/**
 * The push channel (README): a contact's {@code push:topic} address is an ntfy topic; each message is one HTTPS
 * publish ({@link NtfyClient}). The status says whether the last message was taken, and why not in words.
 */
@Component(service = MessageChannel.class, configurationPid = "org.tinysep.push", immediate = true,
        property = MessageChannel.SCHEME + "=push")
@Designate(ocd = PushConfig.class)
public final class PushChannel implements MessageChannel {

    private static final Logger LOG = LoggerFactory.getLogger(PushChannel.class);

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile EventLog eventLog;
    private PushSettings settings;
    private volatile DeviceStatus status;

    @Activate
    void activate(BundleContext context, PushConfig c) {
        start(PushSettings.parse(c, StateFolder.resolveOrDataArea("", context, "secrets/push.token")));
    }

    /** The activation without OSGi (tests). */
    void start(PushSettings s) {
        this.settings = s;
        this.status = s.server() == null ? new DeviceStatus(DeviceStatus.State.ERROR, s.problem() + "; alerts go "
                + "by the other channels", Instant.now()) : new DeviceStatus(DeviceStatus.State.UNKNOWN,
                        "nothing published to " + s.server().getHost() + " yet", Instant.now());
        String warning = PushToken.warning(s.tokenFile());
        if (!warning.isEmpty()) {
            record(EventKind.PROBLEM, warning);
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

    @Override
    public ChannelDelivery send(String topic, ChannelMessage m) {
        ChannelDelivery d = NtfyClient.publish(settings, topic, m);
        boolean ok = d.outcome() != MailDelivery.Outcome.FAILED;
        DeviceStatus before = status;
        status = new DeviceStatus(ok ? DeviceStatus.State.ONLINE : DeviceStatus.State.ERROR, ok ? "last message "
                + d.detail() : d.detail() + "; alerts go by the other channels", Instant.now());
        if (before.state() != status.state()) {
            record(ok ? EventKind.DEVICE_EVENT : EventKind.PROBLEM, "push channel " + (ok ? "working: " : "in ERROR: ")
                    + status.detail());
        }
        return d;
    }

    private void record(EventKind kind, String text) {
        LOG.info("Push: {}", text);
        EventLog l = eventLog;
        if (l != null) {
            l.record(kind, "Push", text);
        }
    }
}
