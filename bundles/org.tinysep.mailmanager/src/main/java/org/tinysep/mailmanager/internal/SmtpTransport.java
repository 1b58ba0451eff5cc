package org.tinysep.mailmanager.internal;

import jakarta.mail.Message;
import jakarta.mail.MessagingException;
import jakarta.mail.SendFailedException;
import jakarta.mail.Session;
import jakarta.mail.Transport;
import jakarta.mail.internet.InternetAddress;
import jakarta.mail.internet.MimeMessage;
import java.nio.charset.StandardCharsets;
import java.util.Date;
import java.util.Properties;
import org.eclipse.angus.mail.smtp.SMTPAddressFailedException;
import org.eclipse.angus.mail.smtp.SMTPSendFailedException;

/**
 * Sends one message through SMTP with Jakarta Mail (embedded privately in this bundle). Jakarta Mail and
 * Activation find their providers through {@code ServiceLoader} and {@code META-INF} resources of the thread
 * context class loader, so that is set to this bundle's class loader around every use.
 */
final class SmtpTransport {

    /** How an attempt ended. */
    enum Outcome {
        SENT,
        /** Sent to some recipients, refused for others (reported, not retried). */
        PARTIAL,
        /** Refused for good by the server (5xx reply): retrying cannot help. */
        REFUSED,
        /** Server unreachable, busy or temporarily failing: retry later. */
        RETRY
    }

    /** @param detail a sentence for the log; never contains the password */
    record Result(Outcome outcome, String detail) {
    }

    Result send(MailSettings s, MailMessage m) {
        Thread thread = Thread.currentThread();
        ClassLoader old = thread.getContextClassLoader();
        thread.setContextClassLoader(SmtpTransport.class.getClassLoader());
        try {
            String protocol = s.security() == Security.TLS ? "smtps" : "smtp";
            Session session = Session.getInstance(properties(s, protocol));
            MimeMessage msg = new MimeMessage(session);
            msg.setFrom(new InternetAddress(s.from()));
            msg.setRecipients(Message.RecipientType.TO, InternetAddress.parse(String.join(",", s.recipients())));
            msg.setSubject(m.subject(), StandardCharsets.UTF_8.name());
            msg.setText(m.body(), StandardCharsets.UTF_8.name());
            msg.setSentDate(Date.from(m.queuedAt()));
            msg.setHeader("X-TinySEP-Mail-Id", Long.toString(m.id()));
            try (Transport t = session.getTransport(protocol)) {
                t.connect(s.host(), s.port(), s.user().isEmpty() ? null : s.user(),
                        s.user().isEmpty() ? null : s.password());
                t.sendMessage(msg, msg.getAllRecipients());
            }
            return new Result(Outcome.SENT, "sent to " + String.join(", ", s.recipients()));
        } catch (SendFailedException e) {
            if (e.getValidSentAddresses() != null && e.getValidSentAddresses().length > 0) {
                return new Result(Outcome.PARTIAL, "sent, but refused for " + list(e.getInvalidAddresses())
                        + list(e.getValidUnsentAddresses()) + ": " + describe(e));
            }
            return new Result(permanent(e) ? Outcome.REFUSED : Outcome.RETRY, describe(e));
        } catch (MessagingException | RuntimeException e) {
            return new Result(Outcome.RETRY, describe(e));
        } finally {
            thread.setContextClassLoader(old);
        }
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

    /** A 5xx reply to MAIL, RCPT or DATA: the server will not take this message, however often we try. */
    private static boolean permanent(Throwable e) {
        for (Throwable t = e; t != null; t = next(t)) {
            int code = t instanceof SMTPSendFailedException f ? f.getReturnCode()
                    : t instanceof SMTPAddressFailedException a ? a.getReturnCode() : 0;
            if (code >= 500 && code < 600) {
                return true;
            }
        }
        return false;
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

    private static String list(jakarta.mail.Address[] addresses) {
        if (addresses == null || addresses.length == 0) {
            return "";
        }
        StringBuilder b = new StringBuilder();
        for (jakarta.mail.Address a : addresses) {
            b.append(b.length() == 0 ? "" : ", ").append(a);
        }
        return b.toString();
    }
}
