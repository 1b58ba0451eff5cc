package org.tinysep.testsupport.mail;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Locale;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocket;

/**
 * One client's SMTP conversation with a {@link SmtpSink}: the envelope being built, whether the client logged in
 * and whether the connection is inside TLS. The sink's settings decide the replies (refused and full mailboxes, the
 * login it requires, STARTTLS).
 */
final class SmtpDialogue {

    private static final String USERNAME = Base64.getEncoder().encodeToString("Username:".getBytes(StandardCharsets.US_ASCII));
    private static final String PASSWORD = Base64.getEncoder().encodeToString("Password:".getBytes(StandardCharsets.US_ASCII));

    private final SmtpSink sink;
    private Socket socket;
    private BufferedReader in;
    private OutputStream out;
    private boolean secure;
    private boolean loggedIn;
    private String from;
    private final List<String> to = new ArrayList<>();

    SmtpDialogue(SmtpSink sink, Socket socket) {
        this.sink = sink;
        this.socket = socket;
    }

    /** Converses until QUIT or the end of the connection; a broken session ends, the server goes on. */
    void run() {
        try (Socket c = socket) {
            c.setSoTimeout(60_000);
            if (c instanceof SSLSocket s) {
                handshake(s);
            }
            open(c);
            reply("220 smtp-sink ESMTP ready");
            for (String line; (line = in.readLine()) != null; ) {
                if (!answer(line)) {
                    return;
                }
            }
        } catch (IOException e) {
            // closed by stop() or by the client, or a refused certificate
        } finally {
            SmtpSink.closeQuietly(socket);
        }
    }

    /** @return false once the conversation is over */
    private boolean answer(String line) throws IOException {
        String verb = (line.length() < 4 ? line : line.substring(0, 4)).toUpperCase(Locale.ROOT);
        switch (verb) {
            case "EHLO" -> ehlo();
            case "HELO" -> reply("250 smtp-sink");
            case "STAR" -> startTls(line);
            case "AUTH" -> auth(line);
            case "MAIL" -> mail(line);
            case "RCPT" -> rcpt(line);
            case "DATA" -> {
                return data();
            }
            case "RSET" -> {
                reset();
                reply("250 reset");
            }
            case "NOOP" -> reply("250 ok");
            case "QUIT" -> {
                reply("221 bye");
                return false;
            }
            default -> reply("502 command not implemented");
        }
        return true;
    }

    private void ehlo() throws IOException {
        List<String> lines = new ArrayList<>(List.of("smtp-sink", "8BITMIME"));
        if (sink.startTls() != null && !secure) {
            lines.add("STARTTLS");
        }
        if (sink.login() != null) {
            lines.add("AUTH PLAIN LOGIN");
        }
        lines.add("SMTPUTF8");
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < lines.size(); i++) {
            b.append(i > 0 ? "\r\n" : "").append(i < lines.size() - 1 ? "250-" : "250 ").append(lines.get(i));
        }
        reply(b.toString());
    }

    private void startTls(String line) throws IOException {
        SSLContext tls = sink.startTls();
        if (!line.equalsIgnoreCase("STARTTLS") || tls == null || secure) {
            reply("502 command not implemented");
            return;
        }
        reply("220 2.0.0 ready to start TLS");
        SSLSocket s = (SSLSocket) tls.getSocketFactory().createSocket(socket, "127.0.0.1", socket.getPort(), true);
        s.setUseClientMode(false);
        handshake(s);
        socket = s;
        open(s);
        reset(); // RFC 3207 4.2: forget what the client said before TLS
        loggedIn = false;
    }

    private void auth(String line) throws IOException {
        SmtpSink.Login login = sink.login();
        String[] words = line.split(" ");
        String mechanism = words.length > 1 ? words[1].toUpperCase(Locale.ROOT) : "";
        if (login == null || !(mechanism.equals("PLAIN") || mechanism.equals("LOGIN"))) {
            reply("504 5.5.4 unrecognised authentication type");
            return;
        }
        String user;
        String password;
        try {
            if (mechanism.equals("PLAIN")) {
                String[] parts = decode(words.length > 2 ? words[2] : challenge("")).split("\0", -1);
                user = parts.length == 3 ? parts[1] : null;
                password = parts.length == 3 ? parts[2] : null;
            } else {
                user = decode(words.length > 2 ? words[2] : challenge(USERNAME));
                password = decode(challenge(PASSWORD));
            }
        } catch (IllegalArgumentException e) {
            reply("501 5.5.2 cannot decode the response");
            return;
        }
        loggedIn = login.user().equals(user) && login.password().equals(password);
        reply(loggedIn ? "235 2.7.0 authentication successful" : "535 5.7.8 authentication credentials invalid");
    }

    private String challenge(String prompt) throws IOException {
        reply("334 " + prompt);
        String answer = in.readLine();
        if (answer == null || answer.equals("*")) {
            throw new IllegalArgumentException("cancelled");
        }
        return answer;
    }

    private void mail(String line) throws IOException {
        if (sink.startTls() != null && !secure) {
            reply("530 5.7.0 must issue a STARTTLS command first");
        } else if (sink.login() != null && !loggedIn) {
            reply("530 5.7.0 authentication required");
        } else {
            reset();
            from = address(line);
            reply("250 sender ok");
        }
    }

    private void rcpt(String line) throws IOException {
        String refusal = sink.refusal(address(line));
        if (from == null) {
            reply("503 5.5.1 need MAIL FROM first");
        } else if (refusal != null) {
            reply(refusal);
        } else {
            to.add(address(line));
            reply("250 recipient ok");
        }
    }

    /** @return false if the connection ended inside the message */
    private boolean data() throws IOException {
        if (from == null) {
            reply("503 5.5.1 need MAIL FROM and RCPT TO first");
            return true;
        }
        if (to.isEmpty()) {
            reply("554 5.5.1 no valid recipients");
            return true;
        }
        reply("354 end with <CRLF>.<CRLF>");
        StringBuilder b = new StringBuilder();
        for (String line; (line = in.readLine()) != null; ) {
            if (line.equals(".")) {
                sink.received.add(new SmtpSink.Received(from, List.copyOf(to), b.toString(), secure));
                reset();
                reply("250 message accepted");
                return true;
            }
            b.append(line.startsWith("..") ? line.substring(1) : line).append("\r\n");
        }
        return false;
    }

    private void reset() {
        from = null;
        to.clear();
    }

    private void handshake(SSLSocket s) throws IOException {
        try {
            s.startHandshake();
        } catch (IOException e) {
            sink.handshakeFailures.add(String.valueOf(e.getMessage()));
            throw e;
        }
    }

    private void open(Socket s) throws IOException {
        secure = s instanceof SSLSocket;
        in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
        out = s.getOutputStream();
    }

    private static String decode(String base64) {
        return new String(Base64.getDecoder().decode(base64.strip()), StandardCharsets.UTF_8);
    }

    private static String address(String line) {
        int lt = line.indexOf('<');
        int gt = line.indexOf('>', lt + 1);
        if (lt >= 0 && gt > lt) {
            return line.substring(lt + 1, gt);
        }
        int colon = line.indexOf(':');
        return colon < 0 ? "" : line.substring(colon + 1).strip();
    }

    private void reply(String text) throws IOException {
        out.write((text + "\r\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
    }
}
