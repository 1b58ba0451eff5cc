package org.tinysep.alerts.internal;

import java.util.List;
import org.apache.felix.service.command.Descriptor;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerProvider;

/** The shell commands {@code tinysep:alerts}, {@code tinysep:ack} and {@code tinysep:mails}. */
@Component(service = AlertCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=alerts",
    "osgi.command.function=ack",
    "osgi.command.function=mails"
})
public final class AlertCommands {

    @Reference
    private AlertService alerts;

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile MailManagerProvider mail;

    @Descriptor("lists the open alerts with every message sent about them and what became of it;"
            + " 'tinysep:alerts all' lists the last 20 closed ones too")
    public String alerts(@Descriptor("'all' to include acknowledged and cleared alerts") String... args) {
        boolean all = args.length > 0 && "all".equalsIgnoreCase(args[0]);
        if (args.length > 1 || (args.length == 1 && !all)) {
            throw new IllegalArgumentException("usage: tinysep:alerts [all]");
        }
        List<Alert> list = all ? alerts.recent(20) : alerts.open();
        return list.isEmpty() ? (all ? "(no alerts)" : "(no open alerts)") : AlertListing.of(list);
    }

    @Descriptor("acknowledges an open alert: you take care of it, so it is no longer repeated or passed on to the"
            + " next contact, e.g. tinysep:ack 3 \"Anna\"")
    public String ack(@Descriptor("the alert's id (tinysep:alerts shows it), then optionally who you are")
            String... args) {
        if (args.length < 1 || args.length > 2) {
            throw new IllegalArgumentException("usage: tinysep:ack <id> [\"your name\"]");
        }
        Alert a = alerts.acknowledge(args[0], args.length == 2 ? args[1] : "the TinySEP shell");
        return "alert " + a.id() + " acknowledged by " + a.closedBy() + ": it is not repeated or passed on any more";
    }

    @Descriptor("what became of the messages the Mail Manager was given since it started (sent, retrying,"
            + " failed, only logged), newest last")
    public String mails(@Descriptor("how many, default 20") String... args) {
        int n;
        try {
            n = args.length == 0 ? 20 : Integer.parseInt(args[0]);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("usage: tinysep:mails [N], N a whole number, was '" + args[0] + "'");
        }
        MailManagerProvider m = mail;
        if (m == null) {
            return "(no Mail Manager running)";
        }
        List<MailDelivery> all = m.deliveries();
        if (all.isEmpty()) {
            return "(no messages since the Mail Manager started)";
        }
        StringBuilder b = new StringBuilder();
        all.subList(Math.max(0, all.size() - Math.max(1, n)), all.size()).forEach(d -> b.append("#").append(d.id())
                .append(' ').append(d.outcome()).append(" \"").append(d.subject()).append("\" to ")
                .append(AlertText.who(d.to())).append(" (queued ").append(d.queuedAt()).append("): ").append(d.detail())
                .append('\n'));
        return b.toString().stripTrailing();
    }
}
