package org.tinysep.mqtt.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads one JSON value (objects, arrays, strings, numbers, true/false/null) for incoming commands. Bad input gives
 * an {@link IllegalArgumentException} saying where and what, never anything else; nesting and length are bounded.
 */
final class JsonReader {

    static final int MAX_LENGTH = 16 * 1024;
    private static final int MAX_DEPTH = 16;

    private final String s;
    private int i;

    private JsonReader(String s) {
        this.s = s;
    }

    /** @return the object the text holds */
    static Map<String, Object> object(String text) {
        if (text.length() > MAX_LENGTH) {
            throw new IllegalArgumentException("the payload is longer than " + MAX_LENGTH + " characters");
        }
        JsonReader r = new JsonReader(text);
        r.space();
        if (r.i >= text.length() || text.charAt(r.i) != '{') {
            throw new IllegalArgumentException("the payload is not a JSON object like {\"parameter\":\"on\",\"value\":true}");
        }
        @SuppressWarnings("unchecked")
        Map<String, Object> m = (Map<String, Object>) r.value(0);
        r.space();
        if (r.i != text.length()) {
            throw r.bad("unexpected text after the object");
        }
        return m;
    }

    private Object value(int depth) {
        if (depth > MAX_DEPTH) {
            throw bad("nested too deeply");
        }
        space();
        if (i >= s.length()) {
            throw bad("the payload ends too early");
        }
        char c = s.charAt(i);
        switch (c) {
            case '{':
                return obj(depth);
            case '[':
                return arr(depth);
            case '"':
                return str();
            case 't':
                return word("true", Boolean.TRUE);
            case 'f':
                return word("false", Boolean.FALSE);
            case 'n':
                return word("null", null);
            default:
                if (c == '-' || Character.isDigit(c)) {
                    return num();
                }
                throw bad("unexpected '" + c + "'");
        }
    }

    private Map<String, Object> obj(int depth) {
        Map<String, Object> m = new LinkedHashMap<>();
        i++;
        space();
        if (peek('}')) {
            i++;
            return m;
        }
        while (true) {
            space();
            if (!peek('"')) {
                throw bad("expected a quoted key");
            }
            String k = str();
            space();
            expect(':');
            m.put(k, value(depth + 1));
            space();
            if (peek(',')) {
                i++;
            } else {
                expect('}');
                return m;
            }
        }
    }

    private List<Object> arr(int depth) {
        List<Object> l = new ArrayList<>();
        i++;
        space();
        if (peek(']')) {
            i++;
            return l;
        }
        while (true) {
            l.add(value(depth + 1));
            space();
            if (peek(',')) {
                i++;
            } else {
                expect(']');
                return l;
            }
        }
    }

    private String str() {
        StringBuilder b = new StringBuilder();
        i++;
        while (i < s.length()) {
            char c = s.charAt(i++);
            if (c == '"') {
                return b.toString();
            }
            if (c == '\\') {
                if (i >= s.length()) {
                    break;
                }
                char e = s.charAt(i++);
                switch (e) {
                    case 'n' -> b.append('\n');
                    case 't' -> b.append('\t');
                    case 'r' -> b.append('\r');
                    case 'b' -> b.append('\b');
                    case 'f' -> b.append('\f');
                    case 'u' -> {
                        if (i + 4 > s.length()) {
                            throw bad("a \\u escape is cut short");
                        }
                        try {
                            b.append((char) Integer.parseInt(s.substring(i, i + 4), 16));
                        } catch (NumberFormatException x) {
                            throw bad("a \\u escape is not hexadecimal");
                        }
                        i += 4;
                    }
                    default -> b.append(e);
                }
            } else {
                b.append(c);
            }
        }
        throw bad("a string is not closed");
    }

    private Object num() {
        int start = i;
        while (i < s.length() && "+-0123456789.eE".indexOf(s.charAt(i)) >= 0) {
            i++;
        }
        String n = s.substring(start, i);
        try {
            if (n.contains(".") || n.contains("e") || n.contains("E")) {
                return Double.parseDouble(n);
            }
            return Long.parseLong(n);
        } catch (NumberFormatException e) {
            throw bad("'" + n + "' is not a number");
        }
    }

    private Object word(String w, Object v) {
        if (!s.startsWith(w, i)) {
            throw bad("unexpected text");
        }
        i += w.length();
        return v;
    }

    private boolean peek(char c) {
        return i < s.length() && s.charAt(i) == c;
    }

    private void expect(char c) {
        if (!peek(c)) {
            throw bad("expected '" + c + "'");
        }
        i++;
    }

    private void space() {
        while (i < s.length() && Character.isWhitespace(s.charAt(i))) {
            i++;
        }
    }

    private IllegalArgumentException bad(String what) {
        return new IllegalArgumentException("the payload is not valid JSON: " + what + " at character " + (i + 1));
    }
}
