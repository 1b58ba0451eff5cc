package org.tinysep.alerts.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertListener;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.device.Connection;

/** Issue 27, item 3: a reply from a registered number acknowledges in that contact's name; others are refused. */
class PhoneRepliesTest {

    private static final Instant T = Instant.parse("2026-11-29T03:00:00Z");

    /** Two open alerts, 3 and 4; acknowledging one records who. */
    private static final class Alerts implements AlertService {
        final List<String> acks = new ArrayList<>();
        final List<Alert> open = new ArrayList<>(List.of(raised("3"), raised("4")));

        static Alert raised(String id) {
            return Copies.raised(id, new AlertRequest(AlertKind.FALL, "fall", "", "", T, "TinySEP: fall", ""));
        }

        @Override
        public Alert acknowledge(String id, String by) {
            Alert a = open.stream().filter(x -> x.id().equals(id)).findFirst().orElseThrow(
                    () -> new IllegalArgumentException("there is no alert " + id));
            open.remove(a);
            acks.add(id + " by " + by);
            return Copies.closed(a, AlertState.ACKNOWLEDGED, T, by);
        }

        @Override
        public List<Alert> open() {
            return List.copyOf(open);
        }

        @Override
        public Alert raise(AlertRequest request) {
            throw new UnsupportedOperationException();
        }

        @Override
        public List<Alert> clear(String source, String why) {
            throw new UnsupportedOperationException();
        }

        @Override
        public List<Alert> recent(int max) {
            return open();
        }

        @Override
        public Optional<Alert> alert(String id) {
            return Optional.empty();
        }

        @Override
        public Connection connect(AlertListener listener) {
            throw new UnsupportedOperationException();
        }
    }

    private final Alerts alerts = new Alerts();
    private final List<String> log = new ArrayList<>();
    private final PhoneReplies replies = new PhoneReplies(ContactBook.parse("Eva <sms:+4915112345678>, "
            + "carer@example.org"), alerts, log::add, log::add);

    @Test
    void okWithTheNumberFromARegisteredPhoneAcknowledgesInTheContactsName() {
        assertEquals(Optional.of("TinySEP: alert 3 acknowledged by Eva. It is not repeated or passed on any more."),
                replies.reply("sms", "004915112345678", " ok #3 "));
        assertEquals(List.of("3 by Eva (SMS reply from 004915112345678)"), alerts.acks);
        assertEquals(Optional.of("TinySEP: there is no alert 3"), replies.reply("sms", "+4915112345678", "OK 3"));
        assertEquals(Optional.of("TinySEP: alert 4 acknowledged by Eva. It is not repeated or passed on any more."),
                replies.reply("sms", "+4915112345678", "OK"), "a bare OK while only alert 4 is open");
    }

    @Test
    void anUnknownNumberIsRefusedLoggedAndNotAnswered() {
        assertEquals(Optional.empty(), replies.reply("sms", "+4917000000000", "OK 3"));
        assertTrue(alerts.acks.isEmpty());
        assertEquals(List.of("SMS reply from +4917000000000 refused: that number is not in the contact list, so it "
                + "cannot acknowledge anything ('OK 3'); nothing was sent back"), log);
    }

    @Test
    void anythingElseGetsAnAnswerSayingWhatToWrite() {
        assertTrue(replies.reply("sms", "+4915112345678", "on my way").orElseThrow().contains("reply: OK 3"));
        assertEquals(Optional.of("TinySEP: 2 alerts are open; reply OK and the alert's number, e.g. OK 3"),
                replies.reply("sms", "+4915112345678", "OK"));
        assertTrue(alerts.acks.isEmpty());
    }
}
