package org.tinysep.house.codec;

import java.io.IOException;
import java.io.Writer;

/** Writes the house file byte for byte as House Information's JAXB marshaller did (formatted, UTF-8). */
final class HouseXmlWriter {

    private static final String INDENT = "    ";

    private HouseXmlWriter() {
    }

    static void write(HouseRooms house, Writer out) throws IOException {
        StringBuilder x = new StringBuilder(256 + 256 * house.rooms().size());
        x.append("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n");
        if (house.rooms().isEmpty()) {
            out.write(x.append("<HOUSE_ROOMS/>\n").toString());
            return;
        }
        x.append("<HOUSE_ROOMS>\n");
        int n = 0;
        for (HouseRoom r : house.rooms()) {
            String where = "room #" + ++n + (r.uid().isEmpty() ? "" : " (UID " + r.uid() + ")");
            x.append(INDENT).append("<ROOM>\n");
            element(x, 2, "UID", r.uid(), where);
            element(x, 2, "NAME", r.name(), where);
            element(x, 2, "TYPE", r.type(), where);
            if (r.neighbours().isEmpty()) {
                x.append(INDENT.repeat(2)).append("<NEIGHBORS/>\n");
            } else {
                x.append(INDENT.repeat(2)).append("<NEIGHBORS>\n");
                for (String uid : r.neighbours()) {
                    element(x, 3, "ROOM_UID", uid, where);
                }
                x.append(INDENT.repeat(2)).append("</NEIGHBORS>\n");
            }
            x.append(INDENT).append("</ROOM>\n");
        }
        out.write(x.append("</HOUSE_ROOMS>\n").toString());
    }

    private static void element(StringBuilder x, int depth, String tag, String value, String where) {
        x.append(INDENT.repeat(depth)).append('<').append(tag).append('>');
        escape(x, value, tag, where);
        x.append("</").append(tag).append(">\n");
    }

    /** Escapes as JAXB did: {@code & < >} as entities, carriage return as {@code &#13;}, the rest as is. */
    private static void escape(StringBuilder x, String value, String tag, String where) {
        value.codePoints().forEach(c -> {
            switch (c) {
                case '&' -> x.append("&amp;");
                case '<' -> x.append("&lt;");
                case '>' -> x.append("&gt;");
                case '\r' -> x.append("&#13;");
                default -> {
                    if (!allowed(c)) {
                        throw new IllegalArgumentException(where + ": " + tag + " holds the character "
                                + String.format("U+%04X", c) + ", which an XML file cannot carry");
                    }
                    x.appendCodePoint(c);
                }
            }
        });
    }

    /** @return whether XML 1.0 allows {@code c} in text (its production Char; a lone surrogate is not a Char) */
    private static boolean allowed(int c) {
        return c == '\t' || c == '\n' || c >= 0x20 && c <= 0xD7FF || c >= 0xE000 && c <= 0xFFFD
                || c >= 0x10000 && c <= 0x10FFFF;
    }
}
