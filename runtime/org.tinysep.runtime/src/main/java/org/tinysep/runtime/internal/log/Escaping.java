package org.tinysep.runtime.internal.log;

/**
 * Escapes text fields of log lines: backslash, tab, line feed and carriage return become {@code \\}, {@code \t},
 * {@code \n} and {@code \r}; other control characters become {@code \}{@code uXXXX}. The result is readable and
 * contains no field separator or line break; {@link #unescape} restores the original exactly.
 */
final class Escaping {

    private Escaping() {
    }

    static String escape(String s) {
        int i = 0;
        int n = s.length();
        while (i < n) { // most text needs no escape: look for the first character that does
            char c = s.charAt(i);
            if (c < 0x20 || c == '\\' || c == 0x7F) {
                break;
            }
            i++;
        }
        if (i == n) {
            return s;
        }
        StringBuilder sb = null;
        for (; i < s.length(); i++) {
            char c = s.charAt(i);
            String rep = switch (c) {
                case '\\' -> "\\\\";
                case '\t' -> "\\t";
                case '\n' -> "\\n";
                case '\r' -> "\\r";
                default -> c < 0x20 || c == 0x7F ? String.format("\\u%04x", (int) c) : null;
            };
            if (rep != null && sb == null) {
                sb = new StringBuilder(s.length() + 8).append(s, 0, i);
            }
            if (sb != null) {
                if (rep == null) {
                    sb.append(c);
                } else {
                    sb.append(rep);
                }
            }
        }
        return sb == null ? s : sb.toString();
    }

    /** @throws IllegalArgumentException on an escape sequence {@link #escape} never writes */
    static String unescape(String s) {
        if (s.indexOf('\\') < 0) {
            return s;
        }
        StringBuilder sb = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c != '\\') {
                sb.append(c);
                continue;
            }
            if (++i >= s.length()) {
                throw new IllegalArgumentException("dangling backslash");
            }
            char e = s.charAt(i);
            switch (e) {
                case '\\' -> sb.append('\\');
                case 't' -> sb.append('\t');
                case 'n' -> sb.append('\n');
                case 'r' -> sb.append('\r');
                case 'u' -> {
                    if (i + 4 >= s.length()) {
                        throw new IllegalArgumentException("short \\u escape");
                    }
                    sb.append((char) Integer.parseInt(s.substring(i + 1, i + 5), 16));
                    i += 4;
                }
                default -> throw new IllegalArgumentException("unknown escape \\" + e);
            }
        }
        return sb.toString();
    }

    /** @return upper-case hexadecimal, two digits per byte, no separators; empty for no bytes */
    static String hex(byte[] bytes) {
        return hex(new StringBuilder(bytes.length * 2), bytes).toString();
    }

    /** Appends {@link #hex(byte[])} of {@code bytes} to {@code out}. */
    static StringBuilder hex(StringBuilder out, byte[] bytes) {
        for (byte b : bytes) {
            out.append(HEX[(b >> 4) & 0xF]).append(HEX[b & 0xF]);
        }
        return out;
    }

    private static final char[] HEX = "0123456789ABCDEF".toCharArray();

    /** @throws IllegalArgumentException on an odd length or a non-hex digit */
    static byte[] unhex(String s) {
        if (s.length() % 2 != 0) {
            throw new IllegalArgumentException("odd number of hex digits");
        }
        byte[] out = new byte[s.length() / 2];
        for (int i = 0; i < out.length; i++) {
            int hi = Character.digit(s.charAt(2 * i), 16);
            int lo = Character.digit(s.charAt(2 * i + 1), 16);
            if (hi < 0 || lo < 0) {
                throw new IllegalArgumentException("not a hex digit in '" + s + "'");
            }
            out[i] = (byte) (hi << 4 | lo);
        }
        return out;
    }
}
