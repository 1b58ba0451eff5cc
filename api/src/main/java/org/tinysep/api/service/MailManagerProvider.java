package org.tinysep.api.service;

import java.util.List;
import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** Sends e-mail to the configured recipients (thesis A.14 IMailManager). */
@ProviderType
public interface MailManagerProvider extends Provider<MailManagerListener> {

    /** Queues a message; never blocks on the network. Failures are retried, not thrown. */
    void send(String subject, String body);

    MailStatus status();

    /**
     * Queues a message to the given addresses (escalation to one contact); never blocks on the network.
     *
     * @param to the addresses; empty = the configured recipients
     * @return the message's id, for {@link #delivery(String)}
     * @throws IllegalArgumentException for a malformed address, in plain words
     * @throws UnsupportedOperationException by a provider older than 1.1
     * @since 1.1
     */
    default String sendTo(List<String> to, String subject, String body) {
        throw new UnsupportedOperationException("this Mail Manager cannot send to given addresses");
    }

    /**
     * @return what became of a message sent since the Mail Manager started, or empty when it is not known
     * @since 1.1
     */
    default Optional<MailDelivery> delivery(String id) {
        return Optional.empty();
    }

    /**
     * @return the recent messages (at most the last 100 since the Mail Manager started), oldest first
     * @since 1.1
     */
    default List<MailDelivery> deliveries() {
        return List.of();
    }

    /**
     * @return the configured recipients (the caregivers); empty when not configured
     * @since 1.1
     */
    default List<String> recipients() {
        return List.of();
    }
}
