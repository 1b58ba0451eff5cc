package org.tinysep.api.alert;

import org.osgi.annotation.versioning.ConsumerType;

/** Hears every change of every alert (raised, notified, delivery outcome, acknowledged, cleared). */
@ConsumerType
public interface AlertListener {

    /**
     * Called after the change is saved, on the alert service's own thread; return quickly.
     *
     * @param alert the alert as it is now
     */
    void alertChanged(Alert alert);
}
