package org.tinysep.timecontroller.internal;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.time.OffsetDateTime;
import java.time.format.DateTimeParseException;
import java.util.Locale;
import org.tinysep.api.service.ClockMode;

/**
 * The time synchroniser wire format (docs/time-sync.md): one ASCII line per UDP datagram, tokens separated by
 * spaces. Requests: {@code HELLO}, {@code TICK <seq> <instant> <hmac>}, {@code BYE <seq> <hmac>}. Answers:
 * {@code WELCOME <instant> <mode> <session>}, {@code DONE <seq> <instant>}, {@code ERROR <seq|-> <code> <text>}.
 * Pure parsing and formatting; the HMAC is checked by {@link SyncAuth}.
 */
sealed interface SyncMessage {

    /** Longest datagram accepted, in bytes. */
    int MAX_LENGTH = 256;

    /** {@code HELLO}: discovery; answered with {@code WELCOME}. */
    record Hello() implements SyncMessage {
    }

    /** A request that must carry an HMAC: {@code signed} is its text without the HMAC, {@code mac} null if absent. */
    sealed interface Signed extends SyncMessage {
        long seq();

        String signed();

        String mac();
    }

    /**
     * {@code TICK <seq> <instant> <hmac>}: set the clock to {@code at}, run every listener, answer {@code DONE}.
     * {@code signed} is {@code TICK <seq> <instant>} with the tokens as sent.
     */
    record Tick(long seq, Instant at, String signed, String mac) implements Signed {
    }

    /** {@code BYE <seq> <hmac>}: the synchroniser has finished; the clock returns to REAL. */
    record Bye(long seq, String signed, String mac) implements Signed {
    }

    /** A datagram that is not a valid request; {@code seq} is {@code -} when it could not be read. */
    final class Invalid extends Exception {
        private final String seq;
        private final String code;

        Invalid(String seq, String code, String text) {
            super(text, null, false, false);
            this.seq = seq;
            this.code = code;
        }

        String seq() {
            return seq;
        }

        /** One word: {@code malformed}, {@code unknown-command} or {@code too-long}. */
        String code() {
            return code;
        }

        /** @return the {@code ERROR} answer for this datagram */
        String answer() {
            return error(seq, code, getMessage());
        }
    }

    /** Parses one datagram. */
    static SyncMessage parse(byte[] data, int length) throws Invalid {
        if (length > MAX_LENGTH) {
            throw new Invalid("-", "too-long", length + " bytes, at most " + MAX_LENGTH);
        }
        for (int i = 0; i < length; i++) {
            int b = data[i] & 0xFF;
            if (b >= 0x7F || (b < 0x20 && b != '\t' && b != '\r' && b != '\n')) {
                throw new Invalid("-", "malformed", "not printable ASCII (byte " + i + " is 0x"
                        + Integer.toHexString(b) + ")");
            }
        }
        return parse(new String(data, 0, length, StandardCharsets.US_ASCII));
    }

    /** Parses one request line; surrounding white space and a trailing line end are ignored. */
    static SyncMessage parse(String line) throws Invalid {
        String text = line.strip();
        if (text.isEmpty()) {
            throw new Invalid("-", "malformed", "empty datagram");
        }
        String[] t = text.split("\\s+");
        String command = t[0].toUpperCase(Locale.ROOT);
        switch (command) {
            case "HELLO":
                if (t.length != 1) {
                    throw new Invalid("-", "malformed", "HELLO takes no arguments");
                }
                return new Hello();
            case "TICK": {
                String seq = seq(t);
                if (t.length != 3 && t.length != 4) {
                    throw new Invalid(seq, "malformed", "expected TICK <seq> <ISO-8601 instant> <hmac>");
                }
                checkSeq(seq, t[1]);
                return new Tick(Long.parseLong(seq), instant(seq, t[2]), "TICK " + t[1] + " " + t[2],
                        t.length == 4 ? t[3] : null);
            }
            case "BYE": {
                String seq = seq(t);
                if (t.length != 2 && t.length != 3) {
                    throw new Invalid(seq, "malformed", "expected BYE <seq> <hmac>");
                }
                checkSeq(seq, t[1]);
                return new Bye(Long.parseLong(seq), "BYE " + t[1], t.length == 3 ? t[2] : null);
            }
            default:
                throw new Invalid("-", "unknown-command", "unknown command '" + abbreviate(t[0])
                        + "'; expected HELLO, TICK or BYE");
        }
    }

    private static String seq(String[] t) {
        return t.length > 1 && t[1].matches("\\d{1,18}") ? t[1] : "-";
    }

    private static void checkSeq(String seq, String token) throws Invalid {
        if ("-".equals(seq)) {
            throw new Invalid(seq, "malformed", "sequence number '" + abbreviate(token)
                    + "' is not 0..18 decimal digits");
        }
    }

    private static Instant instant(String seq, String text) throws Invalid {
        try {
            return Instant.parse(text);
        } catch (DateTimeParseException notUtc) {
            try {
                return OffsetDateTime.parse(text).toInstant();
            } catch (DateTimeParseException e) {
                throw new Invalid(seq, "malformed", "'" + abbreviate(text)
                        + "' is not an ISO-8601 instant such as 2026-11-22T10:00:00Z");
            }
        }
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 40) + "...";
    }

    static String welcome(Instant now, ClockMode mode, String session) {
        return "WELCOME " + now + " " + mode + " " + session;
    }

    static String done(long seq, Instant at) {
        return "DONE " + seq + " " + at;
    }

    static String error(String seq, String code, String text) {
        return "ERROR " + seq + " " + code + " " + text;
    }
}
