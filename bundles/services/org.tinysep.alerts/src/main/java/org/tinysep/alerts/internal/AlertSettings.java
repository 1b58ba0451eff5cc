package org.tinysep.alerts.internal;

import java.time.LocalTime;
import java.time.ZoneId;
import java.time.format.DateTimeParseException;
import java.util.List;

/**
 * The validated configuration of the alerts component.
 *
 * @param contacts      the escalation list; empty = the Mail Manager's recipients, no escalation
 * @param summaryTime   null = no daily summary
 */
record AlertSettings(List<String> contacts, int repeatMinutes, int escalateMinutes, LocalTime summaryTime,
        ZoneId zone) {

    static final AlertSettings DEFAULTS = new AlertSettings(List.of(), 10, 15, LocalTime.of(8, 0),
            ZoneId.systemDefault());

    /** @throws IllegalArgumentException one plain sentence naming the key and the bad value */
    static AlertSettings parse(AlertsConfig c) {
        List<String> contacts = ContactBook.parse(c.contacts()).keys(); // plain addresses or named contacts
        if (c.repeatMinutes() < 0 || c.escalateMinutes() < 0) {
            throw new IllegalArgumentException("repeatMinutes and escalateMinutes must be 0 or more, were "
                    + c.repeatMinutes() + " and " + c.escalateMinutes());
        }
        LocalTime summary = null;
        if (!c.summaryTime().isBlank()) {
            try {
                summary = LocalTime.parse(c.summaryTime().strip());
            } catch (DateTimeParseException e) {
                throw new IllegalArgumentException("summaryTime must be a time of day like 08:00, was '"
                        + c.summaryTime() + "'");
            }
        }
        ZoneId zone;
        try {
            zone = c.timeZone().isBlank() ? ZoneId.systemDefault() : ZoneId.of(c.timeZone().strip());
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("timeZone must be a zone like Europe/Berlin or UTC, was '"
                    + c.timeZone() + "'");
        }
        return new AlertSettings(List.copyOf(contacts), c.repeatMinutes(), c.escalateMinutes(), summary, zone);
    }

    /** @return the addresses told once {@code reached} contacts are (empty = the Mail Manager's recipients) */
    List<String> reached(int reached) {
        return contacts.subList(0, Math.min(Math.max(reached, 1), contacts.size()));
    }
}
