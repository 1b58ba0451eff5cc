package org.tinysep.sms.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.testsupport.phone.GammuSmsd;

/**
 * The SMS channel against the real gammu-smsd with Gammu's dummy modem (issue 27, items 2, 3, 5): an alert goes
 * out through the files spool, a reply from the phone reaches the reply handler and its answer goes back, a refused
 * reply gets no answer, and a daemon that is not running puts the channel in ERROR with send failing at once.
 */
class SmsChannelGammuTest {

    private static final String EVA = "+4915112345678";
    @TempDir
    Path dir;
    private final SmsChannel channel = new SmsChannel();
    private final List<String> replies = new CopyOnWriteArrayList<>();

    @AfterEach
    void stop() {
        channel.deactivate();
    }

    @Test
    void anAlertGoesOutByGammuSmsdAndAReplyIsAnsweredBySms() throws Exception {
        assumeTrue(GammuSmsd.installed(), "gammu-smsd is installed by scripts/install-deps.sh");
        try (GammuSmsd smsd = new GammuSmsd(dir).start()) {
            channel.start(smsd.spool(), smsd.pidFile().toString(), 30, 3, 100);
            channel.use((scheme, from, text) -> {
                replies.add(scheme + " " + from + " " + text);
                return from.equals(EVA) ? Optional.of("TinySEP: alert 3 acknowledged by Eva.") : Optional.empty();
            });
            assertEquals(DeviceStatus.State.ONLINE, channel.status().state(), channel.status().toString());
            ChannelDelivery d = channel.send(EVA, new ChannelMessage("3", "TinySEP: no activity in Bathroom since "
                    + "14:02 [alert 3]", "Not acknowledged yet. Reply OK 3 if you take care of it."));
            assertEquals(MailDelivery.Outcome.QUEUED, d.outcome(), d.detail());
            assertTrue(d.detail().contains("1 SMS to " + EVA + " handed to gammu-smsd (GSM 7-bit)"), d.detail());
            await(() -> channel.delivery(d.id()).orElseThrow().outcome() == MailDelivery.Outcome.SENT, smsd);
            assertEquals(List.of(EVA + ": TinySEP: no activity in Bathroom since 14:02 [alert 3]\nNot acknowledged "
                    + "yet. Reply OK 3 if you take care of it."), smsd.sent());

            smsd.phoneSends(EVA, "ok 3");
            await(() -> smsd.sent().size() == 2, smsd);
            assertEquals(List.of("sms " + EVA + " ok 3"), replies);
            assertEquals(EVA + ": TinySEP: alert 3 acknowledged by Eva.", smsd.sent().get(1));

            smsd.phoneSends("+4917000000000", "OK 3");
            await(() -> replies.size() == 2, smsd);
            Thread.sleep(1500); // an answer would be sent within this
            assertEquals(2, smsd.sent().size(), "nothing is sent back to a refused number: " + smsd.sent());
            assertTrue(Files.list(smsd.spool().resolve("inbox")).findAny().isEmpty(), "each reply handled once");

            smsd.stop(); // the modem unplugged: gammu-smsd gone
            DeviceStatus s = channel.status();
            assertEquals(DeviceStatus.State.ERROR, s.state());
            assertTrue(s.detail().startsWith("gammu-smsd is not running") && s.detail().contains("alerts go by the "
                    + "other channels"), s.detail());
            ChannelDelivery failed = channel.send(EVA, new ChannelMessage("4", "TinySEP: help", ""));
            assertEquals(MailDelivery.Outcome.FAILED, failed.outcome());
            assertEquals(s.detail(), failed.detail());
        }
    }

    @Test
    void anSmsThatWaitsInTheOutboxMeansTheModemDoesNotSend() throws Exception {
        for (String f : List.of("outbox", "inbox", "sent", "error")) {
            Files.createDirectories(dir.resolve(f));
        }
        Path pid = Files.writeString(dir.resolve("pid"), Long.toString(ProcessHandle.current().pid()));
        channel.start(dir, pid.toString(), 1, 3, 100); // a live process, but nobody takes the outbox
        ChannelDelivery d = channel.send(EVA, new ChannelMessage("5", "TinySEP: fall", "Reply OK 5"));
        assertEquals(MailDelivery.Outcome.QUEUED, d.outcome());
        Files.setLastModifiedTime(dir.resolve("outbox").resolve(d.id()), java.nio.file.attribute.FileTime
                .from(java.time.Instant.now().minusSeconds(5)));
        DeviceStatus s = channel.status();
        assertEquals(DeviceStatus.State.ERROR, s.state());
        assertTrue(s.detail().startsWith("1 SMS waiting in the outbox for more than 1 s: the GSM modem is "
                + "unplugged"), s.detail());
        assertTrue(channel.delivery(d.id()).orElseThrow().detail().contains("waiting in gammu-smsd's outbox: 1 SMS"));
    }

    /**
     * Issue 29 (idle CPU): an idle channel, set up, nothing in the outbox, does not look every pollMillis: it waits
     * idleSeconds, yet a reply that arrives in the inbox is read at once (the inbox is watched).
     */
    @Test
    void anIdleChannelDoesNotLookEachPollYetReadsAReplyAsItArrives() throws Exception {
        for (String f : List.of("outbox", "inbox", "sent", "error")) {
            Files.createDirectories(dir.resolve(f));
        }
        channel.use((scheme, from, text) -> {
            replies.add(from + ": " + text);
            return Optional.empty();
        });
        channel.start(dir, "", 30, 3, 100, 60_000);
        Thread.sleep(2000);
        assertTrue(channel.looks() <= 2, "looks in 2 s idle, pollMillis 100: " + channel.looks());
        Path tmp = dir.resolve("reply.tmp");
        Files.write(tmp, "\uFEFFOK 5".getBytes(java.nio.charset.StandardCharsets.UTF_16LE));
        Files.move(tmp, dir.resolve("inbox").resolve("IN20261130_013000_00_" + EVA + "_00.txt"));
        long t0 = System.nanoTime();
        while (replies.isEmpty() && System.nanoTime() - t0 < 5_000_000_000L) {
            Thread.sleep(20);
        }
        assertEquals(1, replies.size(), "the reply was read within 5 s although the next idle look is a minute away");
        assertEquals(EVA + ": OK 5", replies.get(0));
    }

    /** A condition that may read files. */
    private interface Check {
        boolean ok() throws Exception;
    }

    private static void await(Check done, GammuSmsd smsd) throws Exception {
        long end = System.nanoTime() + Duration.ofSeconds(15).toNanos();
        while (!done.ok()) {
            assertTrue(System.nanoTime() < end, "timed out; gammu-smsd log:\n" + smsd.log());
            Thread.sleep(50);
        }
    }
}
