package org.tinysep.mailmanager.internal;

import java.util.Locale;

/**
 * Which SMTP replies are permanent, following RFC 5321 (see the README, "Retry and give-up policy"):
 * <ul>
 * <li>4yz is a transient negative completion (section 4.2.1): the same request may succeed later, so retry;</li>
 * <li>5yz is a permanent negative completion (4.2.1, and 4.2.5 after DATA): do not repeat the same request;</li>
 * <li>except 552 in reply to RCPT: section 4.5.3.1.10 says RFC 821 wrongly gave "too many recipients" the code 552
 * and that clients SHOULD treat a 552 to RCPT as temporary (like 452); mailbox-full servers send it too;</li>
 * <li>no reply at all (connection refused, reset or timed out) is transient: section 3.8 asks clients to treat a
 * broken connection as if a 451 had been received.</li>
 * </ul>
 * Only replies to the commands of this message's transaction (MAIL, RCPT, DATA) can be permanent: a refused
 * greeting, EHLO, STARTTLS or login concerns the server or this installation's settings, not the alert, and is
 * retried until the give-up age, so that fixing the settings still delivers the alert.
 */
final class SmtpReplies {

    private SmtpReplies() {
    }

    /**
     * @param code    the reply code, 0 when there was no reply
     * @param command the command it answered (e.g. {@code RCPT TO:<a@b>}), or null/empty when not known
     * @return whether retrying the same request cannot help
     */
    static boolean permanent(int code, String command) {
        if (code < 500 || code > 599) {
            return false;
        }
        String verb = verb(command);
        if (!verb.equals("MAIL") && !verb.equals("RCPT") && !verb.equals("DATA")) {
            return false;
        }
        return !(code == 552 && verb.equals("RCPT"));
    }

    /** @return the command word in upper case, e.g. {@code RCPT}; empty when unknown */
    static String verb(String command) {
        if (command == null) {
            return "";
        }
        String c = command.strip().toUpperCase(Locale.ROOT);
        int end = 0;
        while (end < c.length() && Character.isLetter(c.charAt(end))) {
            end++;
        }
        String v = c.substring(0, end);
        return v.equals("") && c.startsWith(".") ? "DATA" : v; // the end of the data is answered as DATA
    }

    /** @return a server reply on one line, e.g. {@code 552 5.2.2 mailbox full} */
    static String oneLine(String reply) {
        return reply == null ? "" : reply.strip().replaceAll("\\s+", " ");
    }
}
