package org.tinysep.json;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads JSON strictly (RFC 8259): objects (in their order), arrays, strings, numbers, true, false, null; only
 * JSON's whitespace and escapes; nothing may follow the value. Bad input gives a {@link JsonException} saying what
 * and at which character, never anything else; length is bounded by the caller and nesting by {@link #MAX_DEPTH}.
 */
public final class JsonReader {

    /** Containers nested deeper than this are refused, so no text can exhaust the stack. */
    public static final int MAX_DEPTH = 16;

    private final String s;
    private final String refusal;
    private final boolean flat;
    private int i;

    private JsonReader(String s, String refusal, boolean flat) {
        this.s = s;
        this.refusal = refusal;
        this.flat = flat;
    }

    /**
     * @return the value: {@link Map} (insertion-ordered), {@link List}, {@link String}, {@link Long} (integers),
     *         {@link Double} (fractions and exponents), {@link Boolean} or null
     */
    public static Object value(String text, int maxLength) {
        JsonReader r = start(text, maxLength, "not valid JSON", false);
        Object v = r.value(0);
        r.end("value");
        return v;
    }

    /** @return the object the text holds, its values as {@link #value} gives them */
    @SuppressWarnings("unchecked")
    public static Map<String, Object> object(String text, int maxLength) {
        JsonReader r = start(text, maxLength, "not valid JSON", false);
        if (!r.peek('{')) {
            throw r.bad("not a JSON object", "'{' expected");
        }
        Map<String, Object> m = (Map<String, Object>) r.value(0);
        r.end("object");
        return m;
    }

    /**
     * Reads one flat object whose values are strings, numbers, booleans or null (e.g. {@code {"by":"Eva"}}): every
     * value comes back as text (a number as written), null as absent.
     */
    public static Map<String, String> flatObject(String text, int maxLength) {
        JsonReader r = start(text, maxLength, "not a flat JSON object", true);
        if (!r.peek('{')) {
            throw r.bad("'{' expected");
        }
        Map<String, String> out = new LinkedHashMap<>();
        r.object(0).forEach((k, v) -> {
            if (v != null) {
                out.put(k, (String) v);
            }
        });
        r.end("object");
        return out;
    }

    private static JsonReader start(String text, int maxLength, String refusal, boolean flat) {
        String t = text == null ? "" : text;
        if (t.length() > maxLength) {
            throw new JsonException("longer than " + maxLength + " characters", 0);
        }
        JsonReader r = new JsonReader(t, refusal, flat);
        r.space();
        return r;
    }

    private void end(String what) {
        space();
        if (i < s.length()) {
            throw bad("nothing may follow the " + what);
        }
    }

    /** Skips whitespace; the text must go on. */
    private void ahead() {
        space();
        if (i >= s.length()) {
            throw bad("the text ends too early");
        }
    }

    private Object value(int depth) {
        if (depth > MAX_DEPTH) {
            throw bad("nested too deeply (more than " + MAX_DEPTH + " levels)");
        }
        ahead();
        char c = s.charAt(i);
        if (flat && depth > 0 && (c == '{' || c == '[')) {
            throw bad("only text, number, true, false or null values are accepted");
        }
        return switch (c) {
            case '{' -> object(depth);
            case '[' -> array(depth);
            case '"' -> string();
            case 't' -> word("true", flat ? "true" : Boolean.TRUE);
            case 'f' -> word("false", flat ? "false" : Boolean.FALSE);
            case 'n' -> word("null", null);
            default -> {
                if (c == '-' || (c >= '0' && c <= '9')) {
                    yield number();
                }
                throw bad("a value expected");
            }
        };
    }

    private Map<String, Object> object(int depth) {
        Map<String, Object> m = new LinkedHashMap<>();
        boolean closed = opens('}');
        while (!closed) {
            ahead();
            if (!peek('"')) {
                throw bad("a quoted key expected");
            }
            String k = string();
            ahead();
            expect(':');
            m.put(k, value(depth + 1));
            closed = closes('}');
        }
        return m;
    }

    private List<Object> array(int depth) {
        List<Object> l = new ArrayList<>();
        boolean closed = opens(']');
        while (!closed) {
            l.add(value(depth + 1));
            closed = closes(']');
        }
        return l;
    }

    /** Steps over an opening bracket. @return whether its container closes at once (is empty) */
    private boolean opens(char close) {
        i++;
        ahead();
        if (peek(close)) {
            i++;
            return true;
        }
        return false;
    }

    /** Steps over what follows a member. @return true at the closing bracket, false after a comma */
    private boolean closes(char close) {
        ahead();
        if (!peek(',') && !peek(close)) {
            throw bad("',' or '" + close + "' expected");
        }
        return s.charAt(i++) == close;
    }

    private String string() {
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

    private Object number() {
        int start = i;
        optional('-');
        if (!optional('0')) {
            digits();
        }
        boolean whole = true;
        if (optional('.')) {
            digits();
            whole = false;
        }
        if (optional('e') || optional('E')) {
            if (!optional('+')) {
                optional('-');
            }
            digits();
            whole = false;
        }
        String n = s.substring(start, i);
        if (flat) {
            return n;
        }
        try {
            if (whole) {
                return Long.parseLong(n);
            }
            double d = Double.parseDouble(n);
            if (Double.isFinite(d)) {
                return d;
            }
        } catch (NumberFormatException e) {
            // a whole number beyond long's range
        }
        i = start;
        throw bad("the number " + n + " is out of range");
    }

    private void digits() {
        if (i >= s.length() || s.charAt(i) < '0' || s.charAt(i) > '9') {
            throw bad("a digit expected");
        }
        while (i < s.length() && s.charAt(i) >= '0' && s.charAt(i) <= '9') {
            i++;
        }
    }

    private Object word(String w, Object v) {
        if (!s.startsWith(w, i)) {
            throw bad("a value expected");
        }
        i += w.length();
        return v;
    }

    private boolean optional(char c) {
        if (peek(c)) {
            i++;
            return true;
        }
        return false;
    }

    private boolean peek(char c) {
        return i < s.length() && s.charAt(i) == c;
    }

    private void expect(char c) {
        if (!peek(c)) {
            throw bad("'" + c + "' expected");
        }
        i++;
    }

    private void space() {
        while (i < s.length() && " \t\n\r".indexOf(s.charAt(i)) >= 0) {
            i++;
        }
    }

    private JsonException bad(String what) {
        return bad(refusal, what);
    }

    private JsonException bad(String refusal, String what) {
        return new JsonException(refusal + ": " + what, i + 1);
    }
}
