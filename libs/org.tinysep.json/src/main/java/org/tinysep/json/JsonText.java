package org.tinysep.json;

/**
 * A cursor over JSON text for {@link JsonReader}: JSON's whitespace, strings with their escapes, number tokens,
 * words, and errors that name the character ({@code position() + 1}). Package-private.
 */
final class JsonText {

    /** The cursor: the index of the next character to read. */
    private int i;
    private final String s;
    /** What a bad text is called in errors, e.g. "not valid JSON". */
    private final String refusal;

    /** A cursor at the first character of {@code s} that is not whitespace. */
    JsonText(String s, String refusal) {
        this.s = s;
        this.refusal = refusal;
        space();
    }

    /** @return the character at the cursor (call {@link #ahead()} first) */
    char current() {
        return s.charAt(i);
    }

    /** Steps over the character at the cursor. @return it */
    char take() {
        return s.charAt(i++);
    }

    boolean peek(char c) {
        return i < s.length() && s.charAt(i) == c;
    }

    boolean optional(char c) {
        if (peek(c)) {
            i++;
            return true;
        }
        return false;
    }

    void expect(char c) {
        if (!optional(c)) {
            throw bad("'" + c + "' expected");
        }
    }

    void space() {
        while (i < s.length() && " \t\n\r".indexOf(s.charAt(i)) >= 0) {
            i++;
        }
    }

    /** Skips whitespace; the text must go on. */
    void ahead() {
        space();
        if (i >= s.length()) {
            throw bad("the text ends too early");
        }
    }

    /** Skips whitespace; the text must end there. */
    void end(String what) {
        space();
        if (i < s.length()) {
            throw bad("nothing may follow the " + what);
        }
    }

    /** Reads a string from its opening quote: only JSON's escapes, no raw control characters. */
    String string() {
        StringBuilder b = new StringBuilder();
        i++;
        while (i < s.length()) {
            char c = s.charAt(i);
            if (c == '"') {
                i++;
                return b.toString();
            }
            if (c < 0x20) {
                throw bad("control character in a string (write it as an escape)");
            }
            i++;
            if (c != '\\') {
                b.append(c);
                continue;
            }
            char e = i < s.length() ? s.charAt(i++) : '"';
            switch (e) {
                case '"', '\\', '/' -> b.append(e);
                case 'b' -> b.append('\b');
                case 'f' -> b.append('\f');
                case 'n' -> b.append('\n');
                case 'r' -> b.append('\r');
                case 't' -> b.append('\t');
                case 'u' -> b.append(unicode());
                default -> {
                    i--;
                    throw bad("unknown escape \\" + e);
                }
            }
        }
        throw bad("a string is not closed");
    }

    private char unicode() {
        int v = 0;
        for (int n = 0; n < 4; n++, i++) {
            int d = i < s.length() ? Character.digit(s.charAt(i), 16) : -1;
            if (d < 0) {
                throw bad("a \\u escape needs 4 hexadecimal digits");
            }
            v = v * 16 + d;
        }
        return (char) v;
    }

    /** Reads a number as JSON writes it (no leading zeros, no bare dot, no plus sign). @return its text */
    String number() {
        int start = i;
        optional('-');
        if (!optional('0')) {
            digits();
        }
        if (optional('.')) {
            digits();
        }
        if (optional('e') || optional('E')) {
            if (!optional('+')) {
                optional('-');
            }
            digits();
        }
        return s.substring(start, i);
    }

    private void digits() {
        if (i >= s.length() || s.charAt(i) < '0' || s.charAt(i) > '9') {
            throw bad("a digit expected");
        }
        while (i < s.length() && s.charAt(i) >= '0' && s.charAt(i) <= '9') {
            i++;
        }
    }

    /** Reads {@code w} (true, false, null). @return {@code v} */
    Object word(String w, Object v) {
        if (!s.startsWith(w, i)) {
            throw bad("a value expected");
        }
        i += w.length();
        return v;
    }

    /** Moves the cursor back by {@code n} characters (to name where a token starts). */
    void back(int n) {
        i -= n;
    }

    JsonException bad(String what) {
        return bad(refusal, what);
    }

    JsonException bad(String refusal, String what) {
        return new JsonException(refusal + ": " + what, i + 1);
    }
}
