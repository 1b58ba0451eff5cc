package org.tinysep.drivers.internal;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLOutputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import javax.xml.stream.XMLStreamWriter;

/**
 * Reads and writes {@code drivers.xml} (thesis Figure 3.5: {@code <DRIVERS_LIST>} of {@code <DRIVER>}s, each
 * {@code FILE_PATH}, {@code FULL_NAME}, {@code ENABLED} (absent = true), {@code STATUS}) with the JDK's StAX: no JAXB
 * context on the start path (issue 29: creating it was ~5 % of the start's CPU, on the thread that starts every
 * application). The file looks as JAXB wrote it before, so lists written by older builds read unchanged. DTDs and
 * external entities are refused; an unknown element, an entry without {@code FILE_PATH}, or two entries with
 * one symbolic name, make the whole file malformed.
 */
final class DriversCodec {

    static final String ROOT = "DRIVERS_LIST";
    static final String DRIVER = "DRIVER";

    /** @return the entries of {@code xml}, in file order; {@code source} names the file in messages */
    List<DriverEntry> read(byte[] xml, String source) throws MalformedDriversException {
        List<String[]> drivers;
        try {
            drivers = parse(xml);
        } catch (XMLStreamException | RuntimeException e) {
            throw new MalformedDriversException(source + ": bad XML: " + reason(e), e);
        }
        List<DriverEntry> entries = new ArrayList<>();
        Set<String> keys = new HashSet<>();
        int n = 0;
        for (String[] d : drivers) {
            n++;
            Boolean enabled = bool(d[2], source, n);
            DriverEntry e = new DriverEntry(d[0], d[1], enabled == null || enabled, d[3]);
            if (e.location().isEmpty()) {
                throw new MalformedDriversException(source + ": DRIVER #" + n + " has no FILE_PATH", null);
            }
            if (!keys.add(e.key())) {
                throw new MalformedDriversException(source + ": DRIVER #" + n + " repeats " + e.key(), null);
            }
            entries.add(e);
        }
        return entries;
    }

    /** @return {FILE_PATH, FULL_NAME, ENABLED, STATUS} per DRIVER (null where absent) */
    private static List<String[]> parse(byte[] xml) throws XMLStreamException {
        XMLInputFactory f = XMLInputFactory.newFactory();
        f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        XMLStreamReader r = f.createXMLStreamReader(new ByteArrayInputStream(xml));
        try {
            List<String[]> out = new ArrayList<>();
            r.nextTag();
            expect(r, ROOT);
            while (r.nextTag() == XMLStreamConstants.START_ELEMENT) {
                expect(r, DRIVER);
                out.add(driver(r));
            }
            while (r.hasNext()) {
                r.next(); // to the end of the document: whatever is malformed after the root fails here
            }
            return out;
        } finally {
            r.close();
        }
    }

    private static String[] driver(XMLStreamReader r) throws XMLStreamException {
        String[] d = new String[4];
        while (r.nextTag() == XMLStreamConstants.START_ELEMENT) {
            int i = switch (r.getLocalName()) {
                case "FILE_PATH" -> 0;
                case "FULL_NAME" -> 1;
                case "ENABLED" -> 2;
                case "STATUS" -> 3;
                default -> -1;
            };
            if (i < 0) {
                expect(r, "FILE_PATH, FULL_NAME, ENABLED or STATUS");
            }
            d[i] = r.getElementText();
        }
        return d;
    }

    /** An unknown element makes the file malformed, as with the JAXB codec before (never half a list). */
    private static void expect(XMLStreamReader r, String expected) throws XMLStreamException {
        if (!expected.equals(r.getLocalName())) {
            throw new XMLStreamException("unexpected element <" + r.getLocalName() + "> (expected " + expected + ")",
                    r.getLocation());
        }
    }

    /** xsd:boolean, as JAXB read it: true/1, false/0 (surrounding blanks allowed); absent is null */
    private static Boolean bool(String text, String source, int n) throws MalformedDriversException {
        if (text == null) {
            return null;
        }
        return switch (text.strip()) {
            case "true", "1" -> true;
            case "false", "0" -> false;
            default -> throw new MalformedDriversException(source + ": DRIVER #" + n + " has ENABLED '" + text.strip()
                    + "' (true or false)", null);
        };
    }

    /** @return the entries as UTF-8 XML, laid out as JAXB's formatted output was; equal lists give equal bytes */
    byte[] write(List<DriverEntry> entries) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            XMLStreamWriter w = XMLOutputFactory.newFactory().createXMLStreamWriter(out, StandardCharsets.UTF_8.name());
            w.writeStartDocument(StandardCharsets.UTF_8.name(), "1.0");
            if (entries.isEmpty()) {
                w.writeCharacters("\n");
                w.writeEmptyElement(ROOT);
            } else {
                w.writeCharacters("\n");
                w.writeStartElement(ROOT);
                for (DriverEntry e : entries) {
                    w.writeCharacters("\n    ");
                    w.writeStartElement(DRIVER);
                    field(w, "FILE_PATH", e.location());
                    field(w, "FULL_NAME", e.symbolicName().isEmpty() ? null : e.symbolicName());
                    field(w, "ENABLED", Boolean.toString(e.enabled()));
                    field(w, "STATUS", e.status().isEmpty() ? null : e.status());
                    w.writeCharacters("\n    ");
                    w.writeEndElement();
                }
                w.writeCharacters("\n");
                w.writeEndElement();
            }
            w.writeCharacters("\n");
            w.writeEndDocument();
            w.close();
        } catch (XMLStreamException e) {
            throw new IllegalStateException("cannot write the drivers list as XML: " + e, e);
        }
        return out.toByteArray();
    }

    private static void field(XMLStreamWriter w, String name, String value) throws XMLStreamException {
        if (value != null) {
            w.writeCharacters("\n        ");
            w.writeStartElement(name);
            w.writeCharacters(value);
            w.writeEndElement();
        }
    }

    /** @return the parser's message with its line and column, on one line */
    private static String reason(Throwable failure) {
        String reason = failure.getMessage() == null ? failure.toString() : failure.getMessage();
        if (failure instanceof XMLStreamException x) {
            String msg = x.getMessage() == null ? "" : x.getMessage();
            int m = msg.indexOf("Message: ");
            reason = (x.getLocation() == null ? "" : "line " + x.getLocation().getLineNumber() + ", column "
                    + x.getLocation().getColumnNumber() + ": ") + (m >= 0 ? msg.substring(m + 9) : msg);
        }
        return reason.replaceAll("\\s+", " ").strip();
    }
}
