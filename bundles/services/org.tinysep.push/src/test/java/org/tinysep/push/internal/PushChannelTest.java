package org.tinysep.push.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.lang.annotation.Annotation;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.testsupport.phone.PushSink;

/**
 * The push channel against a real HTTPS server on 127.0.0.1 (issue 27, items 4 and 5): the message arrives as ntfy
 * JSON with the token from the secrets file; a server whose certificate is not trusted, a wrong token, a server
 * that refuses and plain http are each a FAILED delivery and an ERROR status in words.
 */
class PushChannelTest {

    private static final ChannelMessage ALERT = new ChannelMessage("3", "TinySEP: no activity in Bathroom since "
            + "14:02 [alert 3]", "Not acknowledged yet. Reply OK 3 if you take care of it. Grüße");
    @TempDir
    Path dir;

    private static PushConfig config(String server, Path token, Path trusted) {
        return config(server, token, trusted, 3);
    }

    private static PushConfig config(String server, Path token, Path trusted, int timeoutSeconds) {
        return new PushConfig() {
            public Class<? extends Annotation> annotationType() {
                return PushConfig.class;
            }

            public String server() {
                return server;
            }

            public String tokenFile() {
                return token.toString();
            }

            public String trustedCertificates() {
                return trusted == null ? "" : trusted.toString();
            }

            public int priority() {
                return 5;
            }

            public int timeoutSeconds() {
                return timeoutSeconds;
            }
        };
    }

    @Test
    void anAlertIsPublishedOverTlsWithTheTokenFromTheSecretsFile() throws Exception {
        Path token = Files.writeString(dir.resolve("push.token"), "tk_secret123\n");
        try (PushSink sink = new PushSink(dir, "tk_secret123").start()) {
            PushChannel ch = new PushChannel();
            ch.start(PushSettings.parse(config(sink.url(), token, sink.certificatePem()), null));
            ChannelDelivery queued = ch.send("eva-topic", ALERT);
            ChannelDelivery d = settled(ch, queued);
            assertEquals(MailDelivery.Outcome.SENT, d.outcome(), d.detail());
            assertEquals(queued.id(), d.id());
            assertEquals("taken by the push server 127.0.0.1 for topic eva-topic", d.detail());
            assertEquals(1, sink.published().size());
            String json = sink.published().get(0).body();
            assertTrue(json.contains("\"topic\":\"eva-topic\"") && json.contains("\"priority\":5")
                    && json.contains("\"title\":\"TinySEP: no activity in Bathroom since 14:02 [alert 3]\"")
                    && json.contains("Reply OK 3 if you take care of it. Gr\\u00fc\\u00dfe"), json);
            assertEquals(DeviceStatus.State.ONLINE, ch.status().state());

            sink.answer(500);
            ChannelDelivery refused = settled(ch, ch.send("eva-topic", ALERT));
            assertEquals(MailDelivery.Outcome.FAILED, refused.outcome());
            assertTrue(refused.detail().startsWith("the push server 127.0.0.1 refused it: HTTP 500"), refused.detail());
            assertEquals(DeviceStatus.State.ERROR, ch.status().state());
            assertTrue(ch.status().detail().endsWith("alerts go by the other channels"));
            ch.stop();
        }
    }

    @Test
    void anUntrustedServerAWrongTokenAndPlainHttpAreRefusedInWords() throws Exception {
        Path wrong = Files.writeString(dir.resolve("wrong.token"), "tk_wrong");
        try (PushSink sink = new PushSink(dir, "tk_right").start()) {
            PushChannel ch = new PushChannel();
            ch.start(PushSettings.parse(config(sink.url(), wrong, null), null)); // the JVM does not know the cert
            ChannelDelivery d = settled(ch, ch.send("eva-topic", ALERT));
            assertEquals(MailDelivery.Outcome.FAILED, d.outcome());
            assertTrue(d.detail().startsWith("the push server 127.0.0.1 is not trusted (TLS:"), d.detail());

            ch.start(PushSettings.parse(config(sink.url(), wrong, sink.certificatePem()), null));
            d = settled(ch, ch.send("eva-topic", ALERT));
            assertTrue(d.detail().startsWith("the push server 127.0.0.1 refused it: HTTP 401 (the token in " + wrong
                    + " is missing or not allowed to publish to eva-topic)"), d.detail());
            assertTrue(sink.published().isEmpty());
            ch.stop();
        }
        PushChannel plain = new PushChannel();
        plain.start(PushSettings.parse(config("http://127.0.0.1:1", wrong, null), null));
        assertEquals(DeviceStatus.State.ERROR, plain.status().state());
        assertTrue(plain.status().detail().contains("must be an https:// address"), plain.status().detail());
        assertTrue(plain.send("t", ALERT).detail().contains("must be an https:// address"));
        plain.stop();
    }

    /**
     * Issue 27 follow-up: a push server that takes the connection and never answers holds neither the caller (the
     * alert service's thread) nor the next contact's push; its message fails after the timeout, in words.
     */
    @Test
    void aHangingServerHoldsNeitherTheCallerNorTheNextContactsPush() throws Exception {
        Path token = Files.writeString(dir.resolve("push.token"), "tk\n");
        try (ServerSocket hanging = new ServerSocket(0, 10, InetAddress.getLoopbackAddress()); // never accepts
                PushSink sink = new PushSink(dir, "tk").start()) {
            PushChannel evas = new PushChannel();
            evas.start(PushSettings.parse(config("https://127.0.0.1:" + hanging.getLocalPort(), token, null, 4),
                    null));
            PushChannel ottos = new PushChannel();
            ottos.start(PushSettings.parse(config(sink.url(), token, sink.certificatePem()), null));
            long t0 = System.nanoTime();
            ChannelDelivery eva = evas.send("eva-topic", ALERT);
            long held = (System.nanoTime() - t0) / 1_000_000;
            ChannelDelivery otto = ottos.send("otto-topic", ALERT);
            ChannelDelivery evaAgain = evas.send("eva-topic", ALERT); // the same hanging server, another thread
            assertTrue(held < 1000, "the caller was held " + held + " ms by a server that does not answer");
            assertEquals(MailDelivery.Outcome.QUEUED, eva.outcome(), eva.detail());
            assertEquals("waiting for the answer of the push server 127.0.0.1 (at most 8 s)", eva.detail());

            assertEquals(MailDelivery.Outcome.SENT, settled(ottos, otto).outcome());
            long ottoTaken = (System.nanoTime() - t0) / 1_000_000;
            assertEquals(MailDelivery.Outcome.QUEUED, evas.delivery(eva.id()).orElseThrow().outcome(),
                    "Eva's server still hangs when Otto's push was taken, " + ottoTaken + " ms after Eva's send");
            assertEquals(1, sink.published().size());

            ChannelDelivery failed = settled(evas, eva);
            long waited = (System.nanoTime() - t0) / 1_000_000;
            assertEquals(MailDelivery.Outcome.FAILED, failed.outcome());
            assertTrue(failed.detail().startsWith("the push server 127.0.0.1 could not be reached ("),
                    failed.detail());
            assertTrue(waited >= 3500, "failed after the 4 s timeout, not before: " + waited + " ms");
            assertEquals(MailDelivery.Outcome.FAILED, settled(evas, evaAgain).outcome());
            assertEquals(DeviceStatus.State.ERROR, evas.status().state());
            System.out.println("PushChannelTest: caller held " + held + " ms; Otto's push taken after " + ottoTaken
                    + " ms; Eva's failed after " + waited + " ms");
            evas.stop();
            ottos.stop();
        }
    }

    /** @return the outcome of a message sent: QUEUED at once, then what the server said (within 15 s) */
    private static ChannelDelivery settled(PushChannel ch, ChannelDelivery queued) throws InterruptedException {
        if (queued.outcome() != MailDelivery.Outcome.QUEUED) {
            return queued;
        }
        long end = System.nanoTime() + 15_000_000_000L;
        while (System.nanoTime() < end) {
            ChannelDelivery d = ch.delivery(queued.id()).orElseThrow();
            if (d.outcome() != MailDelivery.Outcome.QUEUED) {
                return d;
            }
            Thread.sleep(20);
        }
        return fail("no outcome within 15 s: " + ch.delivery(queued.id()));
    }
}
