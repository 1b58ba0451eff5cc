package org.tinysep.api.channel;

import java.util.Objects;

/**
 * A message for a phone: short, because an SMS is.
 *
 * @param alertId the alert it is about (a reply {@code OK <alertId>} acknowledges it), or empty
 * @param title   one line, e.g. "TinySEP: no activity in Bathroom since 14:02"
 * @param text    the rest in few words: how long quiet, how to acknowledge
 */
public record ChannelMessage(String alertId, String title, String text) {

    public ChannelMessage {
        alertId = alertId == null ? "" : alertId;
        Objects.requireNonNull(title, "title");
        text = text == null ? "" : text;
    }
}
