package org.tinysep.mailmanager.internal;

import jakarta.mail.Address;
import jakarta.mail.AuthenticationFailedException;
import jakarta.mail.Message;
import jakarta.mail.MessagingException;
import jakarta.mail.SendFailedException;
import jakarta.mail.Session;
import jakarta.mail.Transport;
import jakarta.mail.internet.InternetAddress;
import jakarta.mail.internet.MimeMessage;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Date;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import org.eclipse.angus.mail.util.MailConnectException;
import org.eclipse.angus.mail.smtp.SMTPAddressFailedException;
import org.eclipse.angus.mail.smtp.SMTPSendFailedException;
import org.tinysep.device.support.files.TrustedCertificates;

/**
 * Sends one message through SMTP with Jakarta Mail (embedded privately in this bundle). Jakarta Mail and
 * Activation find their providers through {@code ServiceLoader} and {@code META-INF} resources of the thread
 * context class loader, so that is set to this bundle's class loader around every use.
 */
final class SmtpTransport {

    /**
     * How an attempt ended, recipient by recipient.
     *
     * @param delivered the recipients the server accepted the message for
     * @param temporary recipient to server reply (or failure) for those to try again later
     * @param permanent recipient to server reply for those refused for good (RFC 5321, see {@link SmtpReplies})
     * @param serverWide the temporary failure was not about particular recipients (no connection, a refused login,
     *                   4xx to MAIL or DATA): the messages behind this one would fail the same way
     */
    record Attempt(List<String> delivered, Map<String, String> temporary, Map<String, String> permanent,
            boolean serverWide) {

        static Attempt allTemporary(List<String> recipients, String why) {
            Map<String, String> t = new LinkedHashMap<>();
            recipients.forEach(r -> t.put(r, why));
            return new Attempt(List.of(), t, Map.of(), true);
        }
    }

    /**
     * Sends one message to {@code recipients}.
     *
     * @param password the SMTP password, read from its file for this attempt; never logged
     */
    Attempt send(MailSettings s, String password, MailMessage m, List<String> recipients) {
        Thread thread = Thread.currentThread();
        ClassLoader old = thread.getContextClassLoader();
        thread.setContextClassLoader(SmtpTransport.class.getClassLoader());
        try {
            String protocol = s.security() == Security.TLS ? "smtps" : "smtp";
            Properties props = properties(s, protocol);
            if (s.trustedCertificates() != null) {
                try {
                    props.put("mail." + protocol + ".ssl.socketFactory", TrustedCertificates.factory(
                            s.trustedCertificates()));
                } catch (java.io.IOException | java.security.GeneralSecurityException e) {
                    return Attempt.allTemporary(recipients, "cannot use the trusted certificates in "
                            + s.trustedCertificates() + " (" + SmtpReplies.oneLine(String.valueOf(e.getMessage()))
                            + ")");
                }
            }
            Session session = Session.getInstance(props);
            MimeMessage msg = new MimeMessage(session);
            msg.setFrom(new InternetAddress(s.from()));
            msg.setRecipients(Message.RecipientType.TO, InternetAddress.parse(String.join(",", recipients)));
            msg.setSubject(m.subject(), StandardCharsets.UTF_8.name());
            msg.setText(m.body(), StandardCharsets.UTF_8.name());
            msg.setSentDate(Date.from(m.queuedAt()));
            msg.setHeader("X-TinySEP-Mail-Id", Long.toString(m.id()));
            try (Transport t = session.getTransport(protocol)) {
                t.connect(s.host(), s.port(), s.user().isEmpty() ? null : s.user(),
                        s.user().isEmpty() ? null : password);
                t.sendMessage(msg, msg.getAllRecipients());
            }
            return new Attempt(List.copyOf(recipients), Map.of(), Map.of(), false);
        } catch (SendFailedException e) {
            return sorted(recipients, e);
        } catch (MessagingException | RuntimeException e) {
            return Attempt.allTemporary(recipients, plain(e, s));
        } finally {
            thread.setContextClassLoader(old);
        }
    }

    /** Sorts the recipients of a refused or partly refused message by the replies the server gave. */
    private static Attempt sorted(List<String> recipients, SendFailedException e) {
        List<String> delivered = new ArrayList<>();
        for (Address a : e.getValidSentAddresses() == null ? new Address[0] : e.getValidSentAddresses()) {
            delivered.add(address(a));
        }
        Map<String, SMTPAddressFailedException> byAddress = new HashMap<>();
        SMTPSendFailedException whole = null;
        for (Throwable t = e; t != null; t = next(t)) {
            if (t instanceof SMTPAddressFailedException a) {
                byAddress.putIfAbsent(address(a.getAddress()).toLowerCase(Locale.ROOT), a);
            } else if (t instanceof SMTPSendFailedException f && whole == null) {
                whole = f;
            }
        }
        Map<String, String> temporary = new LinkedHashMap<>();
        Map<String, String> permanent = new LinkedHashMap<>();
        boolean serverWide = false;
        for (String r : recipients) {
            if (delivered.stream().anyMatch(r::equalsIgnoreCase)) {
                continue;
            }
            SMTPAddressFailedException a = byAddress.get(r.toLowerCase(Locale.ROOT));
            int code = a != null ? a.getReturnCode() : whole != null ? whole.getReturnCode() : 0;
            String command = a != null ? a.getCommand() : whole != null ? whole.getCommand() : null;
            String reply = a != null ? SmtpReplies.oneLine(a.getMessage())
                    : whole != null ? SmtpReplies.oneLine(whole.getMessage()) : describe(e);
            String said = reply + (command == null ? "" : " to " + SmtpReplies.verb(command));
            boolean forGood = SmtpReplies.permanent(code, command);
            (forGood ? permanent : temporary).put(r, said);
            serverWide |= !forGood && a == null;
        }
        return new Attempt(delivered, temporary, permanent, serverWide);
    }

    /** A failure before any reply about the message itself, in plain words. */
    private static String plain(Exception e, MailSettings s) {
        if (e instanceof MailConnectException) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            return "cannot connect to " + s.host() + ":" + s.port() + " ("
                    + SmtpReplies.oneLine(String.valueOf(cause.getMessage())) + ")";
        }
        if (e instanceof AuthenticationFailedException) {
            return "the server refused the login of " + s.user() + " (" + SmtpReplies.oneLine(e.getMessage()) + ")";
        }
        return describe(e);
    }

    private static String address(Address a) {
        return a instanceof InternetAddress ia ? ia.getAddress() : String.valueOf(a);
    }

    private static Properties properties(MailSettings s, String protocol) {
        String p = "mail." + protocol + ".";
        String ms = Long.toString(s.connectTimeoutSeconds() * 1000L);
        Properties props = new Properties();
        props.setProperty("mail.transport.protocol", protocol);
        props.setProperty(p + "host", s.host());
        props.setProperty(p + "port", Integer.toString(s.port()));
        props.setProperty(p + "connectiontimeout", ms);
        props.setProperty(p + "timeout", ms);
        props.setProperty(p + "writetimeout", ms);
        props.setProperty(p + "from", s.from());
        props.setProperty(p + "sendpartial", "true");
        props.setProperty(p + "auth", Boolean.toString(!s.user().isEmpty()));
        props.setProperty(p + "ssl.checkserveridentity", "true");
        if (s.security() == Security.STARTTLS) {
            props.setProperty(p + "starttls.enable", "true");
            props.setProperty(p + "starttls.required", "true");
        }
        return props;
    }

    private static Throwable next(Throwable t) {
        Throwable n = t instanceof MessagingException me && me.getNextException() != null ? me.getNextException()
                : t.getCause();
        return n == t ? null : n;
    }

    /** The exception chain in one line, e.g. "MailConnectException: Couldn't connect ... (ConnectException: ...)". */
    static String describe(Throwable e) {
        StringBuilder b = new StringBuilder();
        int depth = 0;
        for (Throwable t = e; t != null && depth < 4; t = next(t), depth++) {
            b.append(depth == 0 ? "" : " (").append(t.getClass().getSimpleName()).append(": ")
                    .append(String.valueOf(t.getMessage()).strip().replaceAll("\\s+", " "));
        }
        b.append(")".repeat(Math.max(0, depth - 1)));
        return b.toString();
    }
}
