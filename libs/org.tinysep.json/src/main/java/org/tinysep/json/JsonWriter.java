package org.tinysep.json;

import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Writes JSON, either from plain values ({@link #write}) or piece by piece ({@code open('{').field("a", 1)
 * .close('}')}). Values: {@link Map} (an object, in the map's order), {@link Collection} (an array), strings,
 * {@link Integer} and {@link Long} as written, other numbers by their text form (NaN and infinities as null),
 * booleans, enums (their names), null; anything else (e.g. an {@code Instant}) as its text form.
 * <p>
 * Strings get JSON's escapes ({@code \" \\ \n \r \t}, other control characters as {@code \}u escapes). The default
 * writer also writes {@code < > &} and the line separators U+2028/U+2029 as {@code \}u escapes, so no text can break
 * out of a page that embeds it; the {@link #plain()} one leaves them as they are (the MQTT payloads).
 */
public final class JsonWriter {

    private final StringBuilder b = new StringBuilder(256);
    private final boolean htmlSafe;
    private boolean first = true;

    /** A writer that escapes markup characters too. */
    public JsonWriter() {
        this(true);
    }

    private JsonWriter(boolean htmlSafe) {
        this.htmlSafe = htmlSafe;
    }

    /** @return a writer with JSON's escapes only */
    public static JsonWriter plain() {
        return new JsonWriter(false);
    }

    /** @return {@code value} as JSON text, markup characters escaped */
    public static String write(Object value) {
        return new JsonWriter().value(value).toString();
    }

    /** @return {@code value} as JSON text with JSON's escapes only */
    public static String writePlain(Object value) {
        return plain().value(value).toString();
    }

    /** @return an insertion-ordered map from key/value pairs (values may be null), to write as an object */
    public static Map<String, Object> object(Object... keyValues) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (int i = 0; i + 1 < keyValues.length; i += 2) {
            m.put((String) keyValues[i], keyValues[i + 1]);
        }
        return m;
    }

    /** Starts an object ({@code '{'}) or an array ({@code '['}). */
    public JsonWriter open(char c) {
        comma();
        b.append(c);
        first = true;
        return this;
    }

    /** Ends an object ({@code '}'}) or an array ({@code ']'}). */
    public JsonWriter close(char c) {
        b.append(c);
        first = false;
        return this;
    }

    /** Starts an object's member; its value follows. */
    public JsonWriter key(String k) {
        comma();
        quote(k);
        b.append(':');
        first = true;
        return this;
    }

    /** Writes one value (an array's element or a member's value). */
    public JsonWriter value(Object v) {
        if (v instanceof Map<?, ?> map) {
            open('{');
            map.forEach((k, e) -> key(String.valueOf(k)).value(e));
            return close('}');
        }
        if (v instanceof Collection<?> list) {
            open('[');
            list.forEach(this::value);
            return close(']');
        }
        comma();
        if (v == null) {
            b.append("null");
        } else if (v instanceof Boolean || v instanceof Integer || v instanceof Long) {
            b.append(v);
        } else if (v instanceof Number n) {
            b.append(Double.isFinite(n.doubleValue()) ? n.toString() : "null");
        } else if (v instanceof Enum<?> e) {
            quote(e.name());
        } else {
            quote(v.toString());
        }
        first = false;
        return this;
    }

    /** Writes one object member. */
    public JsonWriter field(String k, Object v) {
        return key(k).value(v);
    }

    private void comma() {
        if (!first) {
            b.append(',');
        }
        first = false;
    }

    private void quote(String s) {
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20 || htmlSafe && (c == '<' || c == '>' || c == '&' || c == '\u2028' || c == '\u2029')) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        b.append('"');
    }

    /** @return the JSON written so far */
    @Override
    public String toString() {
        return b.toString();
    }
}
