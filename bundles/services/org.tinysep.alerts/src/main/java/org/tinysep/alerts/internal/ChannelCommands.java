package org.tinysep.alerts.internal;

import java.util.Comparator;
import java.util.List;
import org.apache.felix.service.command.Descriptor;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.device.DeviceStatus;

/** The shell command {@code tinysep:channels}: the ways alerts reach phones and whether each can send. */
@Component(service = ChannelCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=channels"
})
public final class ChannelCommands {

    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile List<MessageChannel> channels;

    @Descriptor("lists the channels alerts can go by besides e-mail (SMS, push) and whether each can send now")
    public String channels() {
        List<MessageChannel> all = channels;
        if (all == null || all.isEmpty()) {
            return "(no SMS or push channel is running: alerts go by e-mail only; see docs/alerts-by-phone.md)";
        }
        StringBuilder b = new StringBuilder();
        for (MessageChannel c : all.stream().sorted(Comparator.comparing(MessageChannel::scheme)).toList()) {
            DeviceStatus s;
            try {
                s = c.status();
            } catch (RuntimeException e) {
                s = new DeviceStatus(DeviceStatus.State.ERROR, "its status cannot be read: " + e, java.time.Instant
                        .now());
            }
            b.append(c.scheme()).append(": ").append(c.name()).append(" - ").append(s.state()).append(s.detail()
                    .isEmpty() ? "" : " (" + s.detail() + ")").append('\n');
        }
        return b.toString().stripTrailing();
    }
}
