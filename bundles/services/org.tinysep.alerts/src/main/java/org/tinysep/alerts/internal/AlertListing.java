package org.tinysep.alerts.internal;

import java.util.List;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.Notification;

/** The text of {@code tinysep:alerts}: one block per alert, its messages indented below it. */
final class AlertListing {

    private AlertListing() {
    }

    static String of(List<Alert> alerts) {
        StringBuilder b = new StringBuilder();
        for (Alert a : alerts) {
            b.append("alert ").append(a.id()).append("  ").append(a.state()).append("  ").append(a.kind())
                    .append("  raised ").append(a.raisedAt()).append(a.roomName().isEmpty() ? "" : "  in "
                    + a.roomName()).append('\n').append("  ").append(a.subject()).append('\n');
            if (!a.isOpen()) {
                b.append("  ").append(a.state().name().toLowerCase()).append(" at ").append(a.closedAt())
                        .append(": ").append(a.closedBy()).append('\n');
            } else {
                b.append("  contacts told: ").append(a.contactsReached()).append("; acknowledge: tinysep:ack ")
                        .append(a.id()).append(" \"your name\"\n");
            }
            for (Notification n : a.notifications()) {
                b.append("    ").append(n.at()).append(' ').append(n.step()).append(" to ").append(AlertText.who(n.to()))
                        .append(Notification.MAIL.equals(n.channel()) ? "" : " by " + ChannelSender.word(n.channel()))
                        .append(n.mailId().isEmpty() ? "" : Notification.MAIL.equals(n.channel())
                                ? " (mail #" + n.mailId() + ")" : " (#" + n.mailId() + ")").append(": ")
                        .append(n.outcome()).append(n.detail().isEmpty() ? "" : " - " + n.detail()).append('\n');
            }
        }
        return b.toString().stripTrailing();
    }
}
