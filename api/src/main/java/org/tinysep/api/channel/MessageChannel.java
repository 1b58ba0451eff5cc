package org.tinysep.api.channel;

import java.util.Optional;
import org.osgi.annotation.versioning.ConsumerType;
import org.tinysep.api.device.DeviceStatus;

/**
 * One way to reach a person, registered as an OSGi service with the property {@value #SCHEME} (e.g. {@code sms},
 * {@code push}). A contact's address for it is written {@code scheme:address} in the alert service's contact list.
 * Implementations never block for long: {@link #send} hands the message over (to a spool, to the channel's own
 * sending thread) and says at once whether that worked; what became of it later is {@link #delivery}.
 */
@ConsumerType
public interface MessageChannel {

    /** Service property: the scheme this channel serves. */
    String SCHEME = "channel.scheme";

    /** @return the scheme of addresses this channel serves, e.g. {@code sms} */
    String scheme();

    /** @return the channel in words for people, e.g. "SMS through the GSM modem" */
    String name();

    /** @return whether the channel can send now; ERROR with the reason in plain words when it cannot */
    DeviceStatus status();

    /**
     * Hands one message over.
     *
     * @param address the contact's address for this scheme (without the {@code scheme:} prefix)
     * @return QUEUED or SENT when handed over, FAILED (with the reason in words) when it could not be
     */
    ChannelDelivery send(String address, ChannelMessage message);

    /** @return the latest word on a message handed over earlier, if the channel still knows it */
    default Optional<ChannelDelivery> delivery(String id) {
        return Optional.empty();
    }
}
