package org.tinysep.web.api.internal;

import org.tinysep.api.alert.Alert;

/**
 * What an alert is about, in the words the caregiver page shows (the same words the MQTT bridge publishes): the
 * kind, and the alert's own explanation (its text: for a FALL alert the impact, the stillness, the turn and where the
 * person was last seen; for a HELP alert who held which switch for how long and how a mistake is cancelled).
 */
final class AlertWords {

    private AlertWords() {
    }

    /** @return the alert's text, or its subject when it has no text */
    static String explanation(Alert a) {
        return a.text() == null || a.text().isBlank() ? a.subject() : a.text();
    }
}
