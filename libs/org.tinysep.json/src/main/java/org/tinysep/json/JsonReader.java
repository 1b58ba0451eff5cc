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

    private final JsonText t;
    private final boolean flat;

    private JsonReader(JsonText t, boolean flat) {
        this.t = t;
        this.flat = flat;
    }

    /**
     * @return the value: {@link Map} (insertion-ordered), {@link List}, {@link String}, {@link Long} (integers),
     *         {@link Double} (fractions and exponents), {@link Boolean} or null
     */
    public static Object value(String text, int maxLength) {
        JsonReader r = start(text, maxLength, "not valid JSON", false);
        Object v = r.value(0);
        r.t.end("value");
        return v;
    }

    /** @return the object the text holds, its values as {@link #value} gives them */
    @SuppressWarnings("unchecked")
    public static Map<String, Object> object(String text, int maxLength) {
        JsonReader r = start(text, maxLength, "not valid JSON", false);
        if (!r.t.peek('{')) {
            throw r.t.bad("not a JSON object", "'{' expected");
        }
        Map<String, Object> m = (Map<String, Object>) r.value(0);
        r.t.end("object");
        return m;
    }

    /**
     * Reads one flat object whose values are strings, numbers, booleans or null (e.g. {@code {"by":"Eva"}}): every
     * value comes back as text (a number as written), null as absent.
     */
    public static Map<String, String> flatObject(String text, int maxLength) {
        JsonReader r = start(text, maxLength, "not a flat JSON object", true);
        if (!r.t.peek('{')) {
            throw r.t.bad("'{' expected");
        }
        Map<String, String> out = new LinkedHashMap<>();
        r.object(0).forEach((k, v) -> {
            if (v != null) {
                out.put(k, (String) v);
            }
        });
        r.t.end("object");
        return out;
    }

    private static JsonReader start(String text, int maxLength, String refusal, boolean flat) {
        String s = text == null ? "" : text;
        if (s.length() > maxLength) {
            throw new JsonException("longer than " + maxLength + " characters", 0);
        }
        return new JsonReader(new JsonText(s, refusal), flat);
    }

    private Object value(int depth) {
        if (depth > MAX_DEPTH) {
            throw t.bad("nested too deeply (more than " + MAX_DEPTH + " levels)");
        }
        t.ahead();
        char c = t.current();
        if (flat && depth > 0 && (c == '{' || c == '[')) {
            throw t.bad("only text, number, true, false or null values are accepted");
        }
        return switch (c) {
            case '{' -> object(depth);
            case '[' -> array(depth);
            case '"' -> t.string();
            case 't' -> t.word("true", flat ? "true" : Boolean.TRUE);
            case 'f' -> t.word("false", flat ? "false" : Boolean.FALSE);
            case 'n' -> t.word("null", null);
            default -> {
                if (c == '-' || (c >= '0' && c <= '9')) {
                    yield number(t.number());
                }
                throw t.bad("a value expected");
            }
        };
    }

    private Object number(String n) {
        if (flat) {
            return n;
        }
        try {
            if (n.indexOf('.') < 0 && n.indexOf('e') < 0 && n.indexOf('E') < 0) {
                return Long.parseLong(n);
            }
            double d = Double.parseDouble(n);
            if (Double.isFinite(d)) {
                return d;
            }
        } catch (NumberFormatException e) {
            // a whole number beyond long's range
        }
        t.back(n.length());
        throw t.bad("the number " + n + " is out of range");
    }

    private Map<String, Object> object(int depth) {
        Map<String, Object> m = new LinkedHashMap<>();
        boolean closed = opens('}');
        while (!closed) {
            t.ahead();
            if (!t.peek('"')) {
                throw t.bad("a quoted key expected");
            }
            String k = t.string();
            t.ahead();
            t.expect(':');
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
        t.take();
        t.ahead();
        return t.optional(close);
    }

    /** Steps over what follows a member. @return true at the closing bracket, false after a comma */
    private boolean closes(char close) {
        t.ahead();
        if (!t.peek(',') && !t.peek(close)) {
            throw t.bad("',' or '" + close + "' expected");
        }
        return t.take() == close;
    }
}
