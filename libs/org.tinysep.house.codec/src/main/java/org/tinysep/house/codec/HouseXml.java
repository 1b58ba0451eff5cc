package org.tinysep.house.codec;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;

/**
 * The house file format, read and written in one place.
 * <p>
 * <b>Reading</b> is strict about the structure and lenient about layout: the root is {@code <HOUSE_ROOMS>}, holding
 * only {@code <ROOM>}s; a room holds {@code <UID>}, {@code <NAME>}, {@code <TYPE>} and {@code <NEIGHBORS>} (of
 * {@code <ROOM_UID>}s), each at most once and in any order; no attributes, no namespaces, no DOCTYPE. White space,
 * comments and processing instructions between elements are skipped; values are stripped.
 * <p>
 * <b>Writing</b> gives the bytes House Information has always written (UTF-8, {@code standalone="yes"}, four spaces
 * per level, {@code <NEIGHBORS/>} for none, {@code & < >} and carriage returns escaped): equal rooms give equal
 * bytes, and what is written reads back to the same records. Callers keep their own (atomic) file writes.
 */
public final class HouseXml {

    private HouseXml() {
    }

    /**
     * @param in     the file's bytes (closed by the caller)
     * @param source names the file in messages, e.g. its path
     * @return the rooms in file order
     * @throws HouseXmlException naming {@code source}, the line and column, and what was expected
     */
    public static HouseRooms read(InputStream in, String source) throws HouseXmlException {
        return HouseXmlReader.read(in, source);
    }

    /** As {@link #read(InputStream, String)} for bytes in memory. */
    public static HouseRooms read(byte[] xml, String source) throws HouseXmlException {
        return read(new ByteArrayInputStream(xml), source);
    }

    /**
     * Writes {@code house} as XML to {@code out}, which must encode UTF-8 (the declaration says so).
     *
     * @throws IllegalArgumentException when a value holds a character XML cannot carry (e.g. U+0000), naming it
     */
    public static void write(HouseRooms house, Writer out) throws IOException {
        HouseXmlWriter.write(house, out);
    }

    /** @return {@code house} as the text of a house file */
    public static String toString(HouseRooms house) {
        StringWriter out = new StringWriter();
        try {
            write(house, out);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringWriter does not fail
        }
        return out.toString();
    }

    /** @return {@code house} as the UTF-8 bytes of a house file */
    public static byte[] toBytes(HouseRooms house) {
        return toString(house).getBytes(StandardCharsets.UTF_8);
    }
}
