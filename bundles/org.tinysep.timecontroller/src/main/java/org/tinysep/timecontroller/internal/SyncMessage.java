package org.tinysep.timecontroller.internal;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.time.OffsetDateTime;
import java.time.format.DateTimeParseException;
import java.util.Locale;
import org.tinysep.api.service.ClockMode;

/**
 * The time synchroniser wire format (docs/time-sync.md): one ASCII line per UDP datagram, tokens separated by
 * spaces. Requests: {@code HELLO}, {@code TICK <seq> <instant>}. Answers: {@code WELCOME <instant> <mode>},
 * {@code DONE <seq> <instant>}, {@code ERROR <seq|-> <code> <text>}. Pure parsing and formatting.
 */
sealed interface SyncMessage {

    /** Longest datagram accepted, in bytes. */
    int MAX_LENGTH = 256;

    /** {@code HELLO}: discovery; answered with {@code WELCOME}. */
    record Hello() implements SyncMessage {
    }

    /** {@code TICK <seq> <instant>}: set the clock to {@code at}, run every listener, answer {@code DONE}. */
    record Tick(long seq, Instant at) implements SyncMessage {
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
            case "TICK":
                String seq = t.length > 1 && t[1].matches("\\d{1,18}") ? t[1] : "-";
                if (t.length != 3) {
                    throw new Invalid(seq, "malformed", "expected TICK <seq> <ISO-8601 instant>");
                }
                if ("-".equals(seq)) {
                    throw new Invalid(seq, "malformed", "sequence number '" + t[1] + "' is not 0..18 decimal digits");
                }
                return new Tick(Long.parseLong(seq), instant(seq, t[2]));
            default:
                throw new Invalid("-", "unknown-command", "unknown command '" + abbreviate(t[0])
                        + "'; expected HELLO or TICK");
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

    static String welcome(Instant now, ClockMode mode) {
        return "WELCOME " + now + " " + mode;
    }

    static String done(long seq, Instant at) {
        return "DONE " + seq + " " + at;
    }

    static String error(String seq, String code, String text) {
        return "ERROR " + seq + " " + code + " " + text;
    }
}
