package org.tinysep.testsupport.mail;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Base64;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The SMTP sink spoken to line by line over a real socket on 127.0.0.1. */
class SmtpSinkTest {

    private final SmtpSink sink = new SmtpSink();

    @AfterEach
    void stop() {
        sink.close();
    }

    /** A client that sends one line and returns the server's whole reply (its last line starts "ddd "). */
    private static final class Client implements AutoCloseable {
        final Socket s;
        final BufferedReader in;
        final OutputStream out;

        Client(int port) throws IOException {
            s = new Socket(InetAddress.getLoopbackAddress(), port);
            s.setSoTimeout(5000);
            in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
            out = s.getOutputStream();
            assertTrue(reply().startsWith("220 "));
        }

        String say(String line) throws IOException {
            out.write((line + "\r\n").getBytes(StandardCharsets.UTF_8));
            out.flush();
            return reply();
        }

        String reply() throws IOException {
            StringBuilder b = new StringBuilder();
            for (String l = in.readLine(); l != null; l = in.readLine()) {
                b.append(l).append('\n');
                if (l.length() < 4 || l.charAt(3) == ' ') {
                    break;
                }
            }
            return b.toString().strip();
        }

        @Override
        public void close() throws IOException {
            s.close();
        }
    }

    private static String b64(String s) {
        return Base64.getEncoder().encodeToString(s.getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void recordsAMessageWithEnvelopeHeadersAndUnstuffedBody() throws Exception {
        sink.start();
        try (Client c = new Client(sink.port())) {
            assertFalse(c.say("EHLO me").contains("AUTH"), "no login asked for");
            assertEquals("250 sender ok", c.say("MAIL FROM:<home@tinysep.test>"));
            assertEquals("250 recipient ok", c.say("RCPT TO:<carer@care.test>"));
            assertEquals("250 recipient ok", c.say("RCPT TO:<kin@kin.test>"));
            assertTrue(c.say("DATA").startsWith("354"));
            c.out.write(("Subject: No movement\r\n\tin the kitchen\r\nTo: carer@care.test\r\n\r\nline 1\r\n"
                    + "..dotted\r\n").getBytes(StandardCharsets.UTF_8));
            assertEquals("250 message accepted", c.say("."));
            assertEquals("221 bye", c.say("QUIT"));
        }
        assertTrue(sink.await(1, Duration.ofSeconds(5)));
        SmtpSink.Received m = sink.messages().get(0);
        assertEquals("home@tinysep.test", m.from());
        assertEquals(List.of("carer@care.test", "kin@kin.test"), m.to());
        assertEquals("No movement in the kitchen", m.subject(), "folded header unfolded");
        assertEquals("carer@care.test", m.header("to"));
        assertEquals("", m.header("From"));
        assertEquals("line 1\r\n.dotted\r\n", m.body());
        assertFalse(m.tls());
        assertEquals(List.of("carer@care.test", "kin@kin.test"), sink.recipients());
    }

    @Test
    void refusedAndFullMailboxesAreAnsweredAsTheTestAsks() throws Exception {
        sink.refuse("Nobody@gone.test");
        sink.mailboxFull("full@care.test", true);
        sink.start();
        try (Client c = new Client(sink.port())) {
            c.say("HELO me");
            assertEquals("503 5.5.1 need MAIL FROM first", c.say("RCPT TO:<a@b.test>"));
            c.say("MAIL FROM:<h@t.test>");
            assertEquals("550 5.1.1 no such user", c.say("RCPT TO:<nobody@gone.test>"));
            assertEquals("552 5.2.2 mailbox full", c.say("RCPT TO:<full@care.test>"));
            assertEquals("554 5.5.1 no valid recipients", c.say("DATA"));
            sink.mailboxFull("full@care.test", false);
            assertEquals("250 recipient ok", c.say("RCPT TO:<full@care.test>"));
        }
    }

    @Test
    void aRequiredLoginIsOfferedCheckedAndNeededBeforeMail() throws Exception {
        sink.requireLogin("alice", "pw").start();
        try (Client c = new Client(sink.port())) {
            assertTrue(c.say("EHLO me").contains("250-AUTH PLAIN LOGIN"));
            assertEquals("530 5.7.0 authentication required", c.say("MAIL FROM:<h@t.test>"));
            assertEquals("535 5.7.8 authentication credentials invalid", c.say("AUTH PLAIN " + b64("\0alice\0no")));
            assertEquals("334 " + b64("Username:"), c.say("AUTH LOGIN"));
            assertEquals("334 " + b64("Password:"), c.say(b64("alice")));
            assertEquals("235 2.7.0 authentication successful", c.say(b64("pw")));
            assertEquals("250 sender ok", c.say("MAIL FROM:<h@t.test>"));
        }
        try (Client c = new Client(sink.port())) {
            assertEquals("334", c.say("AUTH PLAIN"));
            assertEquals("235 2.7.0 authentication successful", c.say(b64("\0alice\0pw")));
        }
    }

    @Test
    void stopClosesThePortAndStartReopensTheSamePort() throws Exception {
        sink.start();
        int port = sink.port();
        Client open = new Client(port);
        sink.stop();
        assertEquals("", open.reply(), "the open connection was closed");
        open.close();
        assertThrows(IOException.class, () -> new Client(port).close());
        sink.start();
        assertEquals(port, sink.port());
        try (Client c = new Client(port)) {
            assertEquals("250 ok", c.say("NOOP"));
        }
    }
}
