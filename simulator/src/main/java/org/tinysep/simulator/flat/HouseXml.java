package org.tinysep.simulator.flat;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/** Reads a House Information XML file (thesis Figure 3.7, {@code <HOUSE_ROOMS><ROOM>...}) with the JDK's DOM. */
public final class HouseXml {

    private HouseXml() {
    }

    /** @throws IllegalArgumentException naming {@code source} (and line/column for bad XML) */
    public static House parse(InputStream in, String source) throws IOException {
        Document doc;
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            f.setExpandEntityReferences(false);
            DocumentBuilder b = f.newDocumentBuilder();
            b.setErrorHandler(null);
            doc = b.parse(in);
        } catch (SAXParseException e) {
            throw new IllegalArgumentException(source + ":" + e.getLineNumber() + ":" + e.getColumnNumber()
                    + ": bad XML: " + e.getMessage(), e);
        } catch (SAXException | ParserConfigurationException e) {
            throw new IllegalArgumentException(source + ": bad XML: " + e.getMessage(), e);
        }
        Element root = doc.getDocumentElement();
        if (!"HOUSE_ROOMS".equals(root.getTagName())) {
            throw new IllegalArgumentException(source + ": root element must be HOUSE_ROOMS, not " + root.getTagName());
        }
        List<Room> rooms = new ArrayList<>();
        NodeList list = root.getElementsByTagName("ROOM");
        for (int i = 0; i < list.getLength(); i++) {
            Element e = (Element) list.item(i);
            String uid = text(e, "UID", source, i);
            List<String> neighbours = new ArrayList<>();
            NodeList n = e.getElementsByTagName("ROOM_UID");
            for (int j = 0; j < n.getLength(); j++) {
                neighbours.add(n.item(j).getTextContent().trim());
            }
            rooms.add(new Room(uid, text(e, "NAME", source, i), text(e, "TYPE", source, i), neighbours));
        }
        try {
            return new House(rooms);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(source + ": " + e.getMessage(), e);
        }
    }

    private static String text(Element room, String tag, String source, int index) {
        NodeList n = room.getElementsByTagName(tag);
        String value = n.getLength() == 0 ? "" : n.item(0).getTextContent().trim();
        if (value.isEmpty()) {
            throw new IllegalArgumentException(source + ": ROOM #" + (index + 1) + " has no " + tag);
        }
        return value;
    }
}
