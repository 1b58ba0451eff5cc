package org.tinysep.api.service;

import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** Sends e-mail to the configured recipients (thesis A.14 IMailManager). */
@ProviderType
public interface MailManagerProvider extends Provider<MailManagerListener> {

    /** Queues a message; never blocks on the network. Failures are retried, not thrown. */
    void send(String subject, String body);

    MailStatus status();
}
