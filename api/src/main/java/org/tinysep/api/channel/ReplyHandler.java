package org.tinysep.api.channel;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;

/**
 * Hears replies that arrive on a {@link MessageChannel} (an SMS to the modem's number). Provided by the alert
 * service: {@code OK 3} from a contact's registered number acknowledges alert 3 in that contact's name.
 */
@ProviderType
public interface ReplyHandler {

    /**
     * @param scheme the channel it came by, e.g. {@code sms}
     * @param from   the sender's address as the channel knows it (a phone number)
     * @param text   what they wrote
     * @return the answer to send back to {@code from} ("alert 3 acknowledged by Eva", or what was wrong); empty when
     *         the sender is refused (unknown number): nothing is sent back, the refusal is logged
     */
    Optional<String> reply(String scheme, String from, String text);
}
