package org.tinysep.alerts.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.service.MailDelivery;

/** Issue 27, item 1: contacts with channels, tried in order, one notification per channel tried. */
class ContactChannelsTest {

    private static final Instant T = Instant.parse("2026-11-29T03:00:00Z");
    private static final String LIST = "Eva <sms:+49-151-1234-5678 push:eva-topic mail:eva@example.org>, "
            + "plain@example.org";

    /** A channel that fails (the modem is unplugged) or takes the message. */
    private record Fake(String scheme, boolean works, List<String> sent) implements MessageChannel {
        @Override
        public String name() {
            return scheme + " channel";
        }

        @Override
        public DeviceStatus status() {
            return works ? DeviceStatus.online(T) : new DeviceStatus(DeviceStatus.State.ERROR, "modem unplugged", T);
        }

        @Override
        public ChannelDelivery send(String address, ChannelMessage m) {
            sent.add(address + ": " + m.title() + " / " + m.text());
            return works ? new ChannelDelivery("p1", MailDelivery.Outcome.QUEUED, "handed to the server")
                    : ChannelDelivery.failed("the GSM modem is not answering");
        }
    }

    @Test
    void contactsAreParsedWithTheirChannelsInOrderAndPlainAddressesStillWork() {
        ContactBook b = ContactBook.parse(LIST);
        assertEquals(List.of("Eva", "plain@example.org"), b.keys());
        assertEquals("[sms:+4915112345678, push:eva-topic, mail:eva@example.org]", b.get("Eva").orElseThrow()
                .addresses().toString());
        assertTrue(b.get("plain@example.org").orElseThrow().plain());
        assertEquals("Eva", b.byPhone("0049 15112345678").orElseThrow().key());
        assertTrue(b.byPhone("+4900000").isEmpty());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ContactBook.parse("Eva <fax:123>"))
                .getMessage().contains("unknown channel 'fax'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ContactBook.parse("Eva <sms:call-me>"))
                .getMessage().contains("a phone number like +4915112345678"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ContactBook.parse("nobody"))
                .getMessage().contains("neither an e-mail address"));
    }

    @Test
    void aFailingSmsFallsBackToPushAndEachChannelTriedIsRecorded() {
        List<String> smsSent = new ArrayList<>();
        List<String> pushSent = new ArrayList<>();
        Map<String, MessageChannel> channels = Map.of("sms", new Fake("sms", false, smsSent), "push",
                new Fake("push", true, pushSent));
        List<String> events = new ArrayList<>();
        AlertSettings s = new AlertSettings(List.of("Eva", "plain@example.org"), 10, 15, LocalTime.of(8, 0),
                ZoneOffset.UTC);
        Notifier n = new Notifier(s, ContactBook.parse(LIST), channels::get, new AlertText(ZoneOffset.UTC), () -> null,
                events::add, events::add);
        Alert a = Copies.raised("3", new AlertRequest(AlertKind.INACTIVITY, "inactivity", "r1", "Bathroom", T,
                "TinySEP: no activity in Bathroom since 02:15", "text"));
        a = n.send(a, new Escalation.Step(NotificationStep.FIRST, List.of("Eva"), 1), T);
        List<Notification> ns = a.notifications();
        assertEquals(2, ns.size(), ns.toString());
        assertEquals("sms", ns.get(0).channel());
        assertEquals(MailDelivery.Outcome.FAILED, ns.get(0).outcome());
        assertEquals("push", ns.get(1).channel());
        assertEquals(MailDelivery.Outcome.QUEUED, ns.get(1).outcome());
        assertEquals(List.of("Eva"), ns.get(1).to());
        assertEquals(List.of("+4915112345678: TinySEP: no activity in Bathroom since 02:15 [alert 3] / Not "
                + "acknowledged yet. Reply OK 3 if you take care of it."), smsSent);
        assertEquals(1, pushSent.size());
        assertEquals(List.of("alert 3: first message to Eva by push to eva-topic (handed to the server), because "
                + "SMS to +4915112345678 failed: the GSM modem is not answering"), events);
    }

    @Test
    void aContactNoChannelReachesIsAProblemInWords() {
        List<String> events = new ArrayList<>();
        AlertSettings s = new AlertSettings(List.of("Eva"), 10, 15, null, ZoneOffset.UTC);
        Notifier n = new Notifier(s, ContactBook.parse("Eva <sms:+4915112345678 mail:eva@example.org>"),
                k -> null, new AlertText(ZoneOffset.UTC), () -> null, events::add, events::add);
        Alert a = Copies.raised("4", new AlertRequest(AlertKind.HELP, "help", "", "", T, "TinySEP: help", ""));
        a = n.send(a, new Escalation.Step(NotificationStep.FIRST, List.of("Eva"), 1), T);
        assertEquals(2, a.notifications().size());
        assertTrue(a.notifications().stream().allMatch(x -> x.outcome() == MailDelivery.Outcome.FAILED));
        assertEquals(List.of("alert 4: first message to Eva NOT reached by any of their channels: SMS to "
                + "+4915112345678 failed: no SMS channel is running (bundle org.tinysep.sms); e-mail to "
                + "eva@example.org failed: no Mail Manager is running"), events);
    }

    @Test
    void anSmsThatFailsLaterIsFollowedByTheContactsNextChannel() {
        List<String> pushSent = new ArrayList<>();
        Map<String, MessageChannel> channels = Map.of("sms", new LaterFailing(), "push", new Fake("push", true,
                pushSent));
        List<String> events = new ArrayList<>();
        AlertSettings s = new AlertSettings(List.of("Eva"), 10, 15, null, ZoneOffset.UTC);
        Notifier n = new Notifier(s, ContactBook.parse("Eva <sms:+4915112345678 push:eva-topic>"), channels::get,
                new AlertText(ZoneOffset.UTC), () -> null, events::add, events::add);
        Alert a = Copies.raised("5", new AlertRequest(AlertKind.FALL, "fall", "", "", T, "TinySEP: fall", ""));
        a = n.send(a, new Escalation.Step(NotificationStep.FIRST, List.of("Eva"), 1), T);
        assertEquals(1, a.notifications().size());
        assertTrue(pushSent.isEmpty());
        LaterFailing.failed = true; // gammu-smsd moved it to error/
        a = n.refresh(a, T.plusSeconds(20));
        assertEquals(2, a.notifications().size(), a.notifications().toString());
        assertEquals(MailDelivery.Outcome.FAILED, a.notifications().get(0).outcome());
        assertEquals("push", a.notifications().get(1).channel());
        assertEquals(T.plusSeconds(20), a.notifications().get(1).at());
        assertEquals(1, pushSent.size());
        assertTrue(events.contains("alert 5: SMS to Eva failed, so the first message went on by push to eva-topic "
                + "(handed to the server)"), events.toString());
        assertEquals(a, n.refresh(a, T.plusSeconds(21)), "once: the contact was tried again since");
    }

    /** An SMS channel that queues, and later says the SMS failed. */
    private static final class LaterFailing implements MessageChannel {
        static volatile boolean failed;

        @Override
        public String scheme() {
            return "sms";
        }

        @Override
        public String name() {
            return "SMS";
        }

        @Override
        public DeviceStatus status() {
            return DeviceStatus.online(T);
        }

        @Override
        public ChannelDelivery send(String address, ChannelMessage m) {
            return new ChannelDelivery("s1", MailDelivery.Outcome.QUEUED, "handed to gammu-smsd");
        }

        @Override
        public java.util.Optional<ChannelDelivery> delivery(String id) {
            return java.util.Optional.of(failed ? new ChannelDelivery(id, MailDelivery.Outcome.FAILED, "gammu-smsd "
                    + "could not send it") : new ChannelDelivery(id, MailDelivery.Outcome.QUEUED, "handed to gammu-smsd"));
        }
    }
}
