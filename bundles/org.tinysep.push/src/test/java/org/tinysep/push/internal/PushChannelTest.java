package org.tinysep.push.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.annotation.Annotation;
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
                return 3;
            }
        };
    }

    @Test
    void anAlertIsPublishedOverTlsWithTheTokenFromTheSecretsFile() throws Exception {
        Path token = Files.writeString(dir.resolve("push.token"), "tk_secret123\n");
        try (PushSink sink = new PushSink(dir, "tk_secret123").start()) {
            PushChannel ch = new PushChannel();
            ch.start(PushSettings.parse(config(sink.url(), token, sink.certificatePem()), null));
            ChannelDelivery d = ch.send("eva-topic", ALERT);
            assertEquals(MailDelivery.Outcome.SENT, d.outcome(), d.detail());
            assertEquals("p1", d.id());
            assertEquals("taken by the push server 127.0.0.1 for topic eva-topic", d.detail());
            assertEquals(1, sink.published().size());
            String json = sink.published().get(0).body();
            assertTrue(json.contains("\"topic\":\"eva-topic\"") && json.contains("\"priority\":5")
                    && json.contains("\"title\":\"TinySEP: no activity in Bathroom since 14:02 [alert 3]\"")
                    && json.contains("Reply OK 3 if you take care of it. Gr\\u00fc\\u00dfe"), json);
            assertEquals(DeviceStatus.State.ONLINE, ch.status().state());

            sink.answer(500);
            ChannelDelivery refused = ch.send("eva-topic", ALERT);
            assertEquals(MailDelivery.Outcome.FAILED, refused.outcome());
            assertTrue(refused.detail().startsWith("the push server 127.0.0.1 refused it: HTTP 500"), refused.detail());
            assertEquals(DeviceStatus.State.ERROR, ch.status().state());
            assertTrue(ch.status().detail().endsWith("alerts go by the other channels"));
        }
    }

    @Test
    void anUntrustedServerAWrongTokenAndPlainHttpAreRefusedInWords() throws Exception {
        Path wrong = Files.writeString(dir.resolve("wrong.token"), "tk_wrong");
        try (PushSink sink = new PushSink(dir, "tk_right").start()) {
            PushChannel ch = new PushChannel();
            ch.start(PushSettings.parse(config(sink.url(), wrong, null), null)); // the JVM does not know the cert
            ChannelDelivery d = ch.send("eva-topic", ALERT);
            assertEquals(MailDelivery.Outcome.FAILED, d.outcome());
            assertTrue(d.detail().startsWith("the push server 127.0.0.1 is not trusted (TLS:"), d.detail());

            ch.start(PushSettings.parse(config(sink.url(), wrong, sink.certificatePem()), null));
            d = ch.send("eva-topic", ALERT);
            assertTrue(d.detail().startsWith("the push server 127.0.0.1 refused it: HTTP 401 (the token in " + wrong
                    + " is missing or not allowed to publish to eva-topic)"), d.detail());
            assertTrue(sink.published().isEmpty());
        }
        PushChannel plain = new PushChannel();
        plain.start(PushSettings.parse(config("http://127.0.0.1:1", wrong, null), null));
        assertEquals(DeviceStatus.State.ERROR, plain.status().state());
        assertTrue(plain.status().detail().contains("must be an https:// address"), plain.status().detail());
        assertTrue(plain.send("t", ALERT).detail().contains("must be an https:// address"));
    }
}
