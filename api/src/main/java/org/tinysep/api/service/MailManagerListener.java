package org.tinysep.api.service;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

@ConsumerType
public interface MailManagerListener {

    void mailStatusChanged(MailManagerProvider source, MailStatus status, Instant at);
}
