package org.tinysep.web.api.internal;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Reads a request body that must be one flat JSON object whose values are strings, numbers, booleans or null
 * (e.g. {@code {"value":"Kitchen"}}): every value comes back as text (null as absent). Anything else is a
 * {@link ApiException} 400 that says where the body is wrong.
 */
public final class JsonBody {

    private final String text;
    private int pos;

    private JsonBody(String text) {
        this.text = text;
    }

    /** @return the object's members, in order */
    public static Map<String, String> parse(String text) {
        JsonBody p = new JsonBody(text == null ? "" : text);
        Map<String, String> out = new LinkedHashMap<>();
        p.skip();
        p.expect('{');
        p.skip();
        if (p.peek() == '}') {
            p.pos++;
        } else {
            while (true) {
                p.skip();
                String key = p.string();
                p.skip();
                p.expect(':');
                p.skip();
                String value = p.value();
                if (value != null) {
                    out.put(key, value);
                }
                p.skip();
                char c = p.next();
                if (c == '}') {
                    break;
                }
                if (c != ',') {
                    throw p.error("',' or '}' expected");
                }
            }
        }
        p.skip();
        if (p.pos < p.text.length()) {
            throw p.error("nothing may follow the object");
        }
        return out;
    }

    private String value() {
        char c = peek();
        if (c == '"') {
            return string();
        }
        if (c == '{' || c == '[') {
            throw error("only text, number, true, false or null values are accepted");
        }
        int start = pos;
        while (pos < text.length() && "+-.eE0123456789truefalsn".indexOf(text.charAt(pos)) >= 0) {
            pos++;
        }
        String word = text.substring(start, pos);
        if (word.equals("null")) {
            return null;
        }
        if (word.equals("true") || word.equals("false") || word.matches("-?\\d+(\\.\\d+)?([eE][+-]?\\d+)?")) {
            return word;
        }
        throw error("a value expected");
    }

    private String string() {
        expect('"');
        StringBuilder sb = new StringBuilder();
        while (true) {
            char c = next();
            if (c == '"') {
                return sb.toString();
            }
            if (c < 0x20) {
                throw error("control character in text");
            }
            if (c != '\\') {
                sb.append(c);
                continue;
            }
            char e = next();
            switch (e) {
                case '"', '\\', '/' -> sb.append(e);
                case 'n' -> sb.append('\n');
                case 'r' -> sb.append('\r');
                case 't' -> sb.append('\t');
                case 'b' -> sb.append('\b');
                case 'f' -> sb.append('\f');
                case 'u' -> {
                    if (pos + 4 > text.length()) {
                        throw error("bad \\u escape");
                    }
                    try {
                        sb.append((char) Integer.parseInt(text.substring(pos, pos + 4), 16));
                    } catch (NumberFormatException ex) {
                        throw error("bad \\u escape");
                    }
                    pos += 4;
                }
                default -> throw error("bad escape \\" + e);
            }
        }
    }

    private void skip() {
        while (pos < text.length() && Character.isWhitespace(text.charAt(pos))) {
            pos++;
        }
    }

    private char peek() {
        if (pos >= text.length()) {
            throw error("the body ends too early");
        }
        return text.charAt(pos);
    }

    private char next() {
        char c = peek();
        pos++;
        return c;
    }

    private void expect(char c) {
        if (next() != c) {
            pos--;
            throw error("'" + c + "' expected");
        }
    }

    private ApiException error(String what) {
        return ApiException.badRequest("the request body is not a flat JSON object: " + what + " at character " + (pos + 1));
    }
}
