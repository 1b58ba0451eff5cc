package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.Objects;
import org.tinysep.api.service.InactivityAlert;

/**
 * A time when Inactivity Recognition was not running (platform stopped, crashed, or the device re-created): from
 * its last saved state to the moment it came back. An alert that fell due in it is late, and says so.
 *
 * @param from the last moment it is known to have been running (its last saved state)
 * @param to   when it came back
 */
record Outage(Instant from, Instant to) {

    Outage {
        Objects.requireNonNull(from, "from");
        Objects.requireNonNull(to, "to");
    }

    /** @return whether the alert fell due while nothing was running: raised only after the restart */
    boolean delayed(InactivityAlert alert) {
        return alert.raisedAt().isAfter(from) && alert.raisedAt().isBefore(to);
    }
}
