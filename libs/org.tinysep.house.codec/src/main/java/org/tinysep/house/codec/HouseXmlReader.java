package org.tinysep.house.codec;

import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;

/** Reads one house file with the JDK's own StAX parser; see {@link HouseXml} for what it accepts. */
final class HouseXmlReader {

    private static final String ROOT = "HOUSE_ROOMS";
    private static final String ROOM = "ROOM";
    private static final String NEIGHBORS = "NEIGHBORS";
    private static final String ROOM_UID = "ROOM_UID";

    private final XMLStreamReader xml;
    private final String source;

    private HouseXmlReader(XMLStreamReader xml, String source) {
        this.xml = xml;
        this.source = source;
    }

    static HouseRooms read(InputStream in, String source) throws HouseXmlException {
        // the JDK's parser, not one found on the class path (inside OSGi the lookup depends on class loaders)
        XMLInputFactory f = XMLInputFactory.newDefaultFactory();
        f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        f.setProperty(XMLInputFactory.IS_COALESCING, true);
        XMLStreamReader xml = null;
        try {
            xml = f.createXMLStreamReader(in);
            return new HouseXmlReader(xml, source).house();
        } catch (XMLStreamException e) {
            Location at = e.getLocation();
            String reason = e.getMessage() == null ? e.toString() : e.getMessage();
            int m = reason.indexOf("Message: ");
            reason = (m >= 0 ? reason.substring(m + 9) : reason).replaceAll("\\s+", " ").strip();
            throw new HouseXmlException(source, at == null ? 0 : Math.max(0, at.getLineNumber()),
                    at == null ? 0 : Math.max(0, at.getColumnNumber()), "bad XML: " + reason, e);
        } finally {
            if (xml != null) {
                try {
                    xml.close();
                } catch (XMLStreamException ignored) {
                    // nothing held beyond the caller's stream
                }
            }
        }
    }

    private HouseRooms house() throws XMLStreamException, HouseXmlException {
        nextTag("<" + ROOT + "> as the root element");
        if (!is(ROOT)) {
            throw fail("expected <" + ROOT + "> as the root element, found " + found());
        }
        noAttributes();
        List<HouseRoom> rooms = new ArrayList<>();
        while (nextTag("<ROOM> or </" + ROOT + ">") == XMLStreamConstants.START_ELEMENT) {
            if (!is(ROOM)) {
                throw fail("expected <ROOM> or </" + ROOT + ">, found " + found());
            }
            rooms.add(room(rooms.size() + 1));
        }
        while (xml.hasNext()) { // after the root: only what the parser allows there (comments, white space)
            if (xml.next() == XMLStreamConstants.DTD) {
                throw doctype();
            }
        }
        return new HouseRooms(rooms);
    }

    private HouseRoom room(int n) throws XMLStreamException, HouseXmlException {
        noAttributes();
        String where = "room #" + n;
        String uid = null;
        String name = null;
        String type = null;
        List<String> neighbours = null;
        String expected = "<UID>, <NAME>, <TYPE>, <NEIGHBORS> or </ROOM> in " + where;
        while (nextTag(expected) == XMLStreamConstants.START_ELEMENT) {
            noAttributes();
            String tag = is(xml.getLocalName()) ? xml.getLocalName() : "";
            switch (tag) {
                case "UID" -> uid = once(uid, text(where), where);
                case "NAME" -> name = once(name, text(where), where);
                case "TYPE" -> type = once(type, text(where), where);
                case NEIGHBORS -> neighbours = once(neighbours, neighbours(where), where);
                default -> throw fail("expected " + expected + ", found " + found());
            }
        }
        return new HouseRoom(orEmpty(uid), orEmpty(name), orEmpty(type), neighbours == null ? List.of() : neighbours);
    }

    private List<String> neighbours(String where) throws XMLStreamException, HouseXmlException {
        List<String> uids = new ArrayList<>();
        while (nextTag("<ROOM_UID> or </NEIGHBORS> in " + where) == XMLStreamConstants.START_ELEMENT) {
            if (!is(ROOM_UID)) {
                throw fail("expected <ROOM_UID> or </NEIGHBORS> in " + where + ", found " + found());
            }
            noAttributes();
            uids.add(text(where));
        }
        return uids;
    }

    /** @return the stripped text of the current element, which must hold no element */
    private String text(String where) throws XMLStreamException, HouseXmlException {
        String tag = xml.getLocalName();
        StringBuilder text = new StringBuilder();
        while (true) {
            switch (xml.next()) {
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA, XMLStreamConstants.SPACE ->
                        text.append(xml.getText());
                case XMLStreamConstants.COMMENT, XMLStreamConstants.PROCESSING_INSTRUCTION -> {
                }
                case XMLStreamConstants.END_ELEMENT -> {
                    return text.toString().strip();
                }
                default -> throw fail("expected the text of <" + tag + "> in " + where + ", found " + found());
            }
        }
    }

    /** @return the next start or end tag, skipping white space, comments and processing instructions */
    private int nextTag(String expected) throws XMLStreamException, HouseXmlException {
        while (true) {
            int event = xml.next();
            switch (event) {
                case XMLStreamConstants.START_ELEMENT, XMLStreamConstants.END_ELEMENT -> {
                    return event;
                }
                case XMLStreamConstants.COMMENT, XMLStreamConstants.PROCESSING_INSTRUCTION, XMLStreamConstants.SPACE -> {
                }
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA -> {
                    if (!xml.isWhiteSpace()) {
                        throw fail("expected " + expected + ", found " + found());
                    }
                }
                case XMLStreamConstants.DTD -> throw doctype();
                default -> throw fail("expected " + expected + ", found " + found());
            }
        }
    }

    private <T> T once(T before, T value, String where) throws HouseXmlException {
        if (before != null) {
            throw fail("<" + xml.getLocalName() + "> given twice in " + where);
        }
        return value;
    }

    private void noAttributes() throws HouseXmlException {
        if (xml.getAttributeCount() > 0) {
            throw fail("<" + xml.getLocalName() + "> has an attribute " + xml.getAttributeName(0)
                    + "; the house file has none");
        }
    }

    /** @return whether the current element is {@code name} without a namespace */
    private boolean is(String name) {
        String ns = xml.getNamespaceURI();
        return (ns == null || ns.isEmpty()) && name.equals(xml.getLocalName());
    }

    /** @return the current event in the words of a message */
    private String found() {
        return switch (xml.getEventType()) {
            case XMLStreamConstants.START_ELEMENT -> "<" + qualified() + ">";
            case XMLStreamConstants.END_ELEMENT -> "</" + qualified() + ">";
            case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA, XMLStreamConstants.SPACE ->
                    "the text '" + clip(xml.getText().strip()) + "'";
            case XMLStreamConstants.END_DOCUMENT -> "the end of the file";
            case XMLStreamConstants.ENTITY_REFERENCE -> "the entity &" + xml.getLocalName() + ";";
            default -> "XML event " + xml.getEventType();
        };
    }

    private String qualified() {
        String prefix = xml.getPrefix();
        String ns = xml.getNamespaceURI();
        return (prefix == null || prefix.isEmpty() ? "" : prefix + ":") + xml.getLocalName()
                + (ns == null || ns.isEmpty() ? "" : " (namespace " + ns + "; the house file uses none)");
    }

    private static String clip(String text) {
        return text.length() <= 40 ? text : text.substring(0, 40) + "...";
    }

    private HouseXmlException doctype() {
        return fail("a DOCTYPE is not allowed in a house file (refused so that no entity or external file is read)");
    }

    private HouseXmlException fail(String reason) {
        Location at = xml.getLocation();
        return new HouseXmlException(source, at == null ? 0 : Math.max(0, at.getLineNumber()),
                at == null ? 0 : Math.max(0, at.getColumnNumber()), reason, null);
    }

    private static String orEmpty(String s) {
        return s == null ? "" : s;
    }
}
