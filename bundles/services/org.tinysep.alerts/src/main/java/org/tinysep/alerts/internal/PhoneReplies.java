package org.tinysep.alerts.internal;

import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertService;

/**
 * Replies from phones: {@code OK 3} (also {@code ok3}, {@code OK #3}, {@code ACK 3}) from a contact's
 * registered number acknowledges alert 3 in that contact's name; a bare {@code OK} acknowledges the only open alert
 * when exactly one is open. A reply from a number not in the contact list is refused: logged, nothing is done and
 * nothing is sent back. Every other reply gets an answer in words saying what happened or what to write.
 */
final class PhoneReplies {

    private static final Pattern OK = Pattern.compile("\\s*(?:OK|ACK)\\s*#?\\s*(\\d*)\\s*[.!]?\\s*",
            Pattern.CASE_INSENSITIVE);

    private final ContactBook contacts;
    private final AlertService alerts;
    private final Consumer<String> events;
    private final Consumer<String> problems;

    PhoneReplies(ContactBook contacts, AlertService alerts, Consumer<String> events, Consumer<String> problems) {
        this.contacts = contacts;
        this.alerts = alerts;
        this.events = events;
        this.problems = problems;
    }

    Optional<String> reply(String scheme, String from, String text) {
        String said = text == null ? "" : text.strip().replaceAll("\\s+", " ");
        String shown = said.length() > 60 ? said.substring(0, 60) + "..." : said;
        String by = ChannelSender.word(scheme);
        Optional<ContactBook.Contact> who = "sms".equals(scheme) ? contacts.byPhone(from) : Optional.empty();
        if (who.isEmpty()) {
            problems.accept(by + " reply from " + from + " refused: that number is not in the contact list, so it "
                    + "cannot acknowledge anything ('" + shown + "'); nothing was sent back");
            return Optional.empty();
        }
        String name = who.get().key();
        Matcher m = OK.matcher(said);
        if (!m.matches()) {
            events.accept(by + " reply from " + name + " (" + from + ") not understood: '" + shown + "'");
            return Optional.of("TinySEP did not understand '" + shown + "'. To take care of alert 3, reply: OK 3");
        }
        String id = m.group(1);
        if (id.isEmpty()) {
            List<Alert> open = alerts.open();
            if (open.size() != 1) {
                events.accept(by + " reply OK from " + name + " without an alert number while " + open.size()
                        + " alerts are open");
                return Optional.of(open.isEmpty() ? "TinySEP: no alert is open, nothing to acknowledge."
                        : "TinySEP: " + open.size() + " alerts are open; reply OK and the alert's number, e.g. OK "
                                + open.get(0).id());
            }
            id = open.get(0).id();
        }
        try {
            alerts.acknowledge(id, name + " (" + by + " reply from " + from + ")");
            return Optional.of("TinySEP: alert " + id + " acknowledged by " + name + ". It is not repeated or "
                    + "passed on any more.");
        } catch (IllegalArgumentException | IllegalStateException e) {
            events.accept(by + " reply '" + shown + "' from " + name + " changed nothing: " + e.getMessage());
            return Optional.of("TinySEP: " + e.getMessage());
        }
    }
}
