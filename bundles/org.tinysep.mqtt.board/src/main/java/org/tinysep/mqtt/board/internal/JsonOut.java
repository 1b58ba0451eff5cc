package org.tinysep.mqtt.board.internal;

/** A small JSON writer: objects and arrays built in order, strings escaped. */
final class JsonOut {

    private final StringBuilder b = new StringBuilder();
    private boolean first = true;

    JsonOut open(char c) {
        comma();
        b.append(c);
        first = true;
        return this;
    }

    JsonOut close(char c) {
        b.append(c);
        first = false;
        return this;
    }

    JsonOut key(String k) {
        comma();
        quote(k);
        b.append(':');
        first = true;
        return this;
    }

    JsonOut value(Object v) {
        comma();
        if (v == null) {
            b.append("null");
        } else if (v instanceof Number || v instanceof Boolean) {
            b.append(v);
        } else {
            quote(v.toString());
        }
        first = false;
        return this;
    }

    JsonOut field(String k, Object v) {
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
                    if (c < 0x20 || c == '<' || c == '>' || c == '&' || c == '\u2028' || c == '\u2029') {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        b.append('"');
    }

    @Override
    public String toString() {
        return b.toString();
    }
}
