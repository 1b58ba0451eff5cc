package org.tinysep.api.service;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

@ConsumerType
public interface InactivityRecognitionListener {

    void inactivityStateChanged(InactivityRecognitionProvider source, InactivityState state, Instant at);
}
