package org.tinysep.api.channel;

import java.util.Objects;
import org.tinysep.api.service.MailDelivery;

/**
 * What became of one message handed to a {@link MessageChannel}.
 *
 * @param id      the channel's id of the message (empty when it was not handed over)
 * @param outcome where it stands (the same words as for mail)
 * @param detail  in plain words, e.g. "SMS to +4915112345678 sent by the modem"
 */
public record ChannelDelivery(String id, MailDelivery.Outcome outcome, String detail) {

    public ChannelDelivery {
        id = id == null ? "" : id;
        Objects.requireNonNull(outcome, "outcome");
        detail = detail == null ? "" : detail;
    }

    /** @return a delivery that failed before it was handed over */
    public static ChannelDelivery failed(String why) {
        return new ChannelDelivery("", MailDelivery.Outcome.FAILED, why);
    }
}
