package org.tinysep.house.codec;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/** What the reader accepts, and the message for each kind of bad file. */
class HouseXmlReadTest {

    static HouseRooms read(String xml) throws HouseXmlException {
        return HouseXml.read(xml.getBytes(StandardCharsets.UTF_8), "h.xml");
    }

    static String refused(String xml) {
        return assertThrows(HouseXmlException.class, () -> read(xml)).getMessage();
    }

    @Test
    void readsRoomsInFileOrderWithValuesStripped() throws Exception {
        HouseRooms h = read("""
                <?xml version="1.0" encoding="UTF-8"?>
                <!-- a comment before the root -->
                <HOUSE_ROOMS>
                  <ROOM>
                    <UID> a </UID><NAME>Bed &amp; <![CDATA[<Study>]]></NAME><TYPE>Bedroom</TYPE>
                    <NEIGHBORS><ROOM_UID>b</ROOM_UID><!-- c later --><ROOM_UID> c </ROOM_UID></NEIGHBORS>
                  </ROOM>
                  <ROOM><TYPE>Hall</TYPE><NEIGHBORS/><NAME>B</NAME><UID>b</UID></ROOM>
                  <ROOM><UID>c</UID></ROOM>
                </HOUSE_ROOMS>
                <!-- and one after -->
                """);
        assertEquals(List.of(new HouseRoom("a", "Bed & <Study>", "Bedroom", List.of("b", "c")),
                new HouseRoom("b", "B", "Hall", List.of()), new HouseRoom("c", "", "", List.of())), h.rooms());
        assertEquals(HouseRooms.EMPTY, read("<HOUSE_ROOMS/>"));
    }

    @Test
    void badXmlNamesLineAndColumn() {
        HouseXmlException e = assertThrows(HouseXmlException.class,
                () -> read("<HOUSE_ROOMS>\n<ROOM>\n  <UID>a</UID>\n  <NAME>A</NAM>\n</ROOM></HOUSE_ROOMS>"));
        assertTrue(e.getMessage().startsWith("h.xml at line 4, column "), e.getMessage());
        assertTrue(e.getMessage().contains("bad XML: ") && e.getMessage().contains("NAME"), e.getMessage());
        assertEquals(4, e.line());
        assertTrue(e.column() > 0, "column " + e.column());
        assertTrue(refused("").startsWith("h.xml"), refused(""));
    }

    @Test
    void unexpectedElementsSayWhatWasExpected() {
        assertEquals("h.xml at line 1, column 9: expected <HOUSE_ROOMS> as the root element, found <HOUSE>",
                refused("<HOUSE/>"));
        assertEquals("h.xml at line 2, column 9: expected <ROOM> or </HOUSE_ROOMS>, found <FLOOR>",
                refused("<HOUSE_ROOMS>\n<FLOOR/></HOUSE_ROOMS>"));
        assertEquals("h.xml at line 3, column 11: expected <UID>, <NAME>, <TYPE>, <NEIGHBORS> or </ROOM> in room #2, "
                + "found <COLOUR>", refused("<HOUSE_ROOMS><ROOM/>\n<ROOM><UID>b</UID>\n  <COLOUR>red</COLOUR></ROOM>"
                        + "</HOUSE_ROOMS>"));
        assertEquals("h.xml at line 1, column 48: expected <ROOM_UID> or </NEIGHBORS> in room #1, found <UID>",
                refused("<HOUSE_ROOMS><ROOM><UID>a</UID><NEIGHBORS><UID>b</UID></NEIGHBORS></ROOM></HOUSE_ROOMS>"));
        assertTrue(refused("<HOUSE_ROOMS><ROOM><NAME>A <B>x</B></NAME></ROOM></HOUSE_ROOMS>")
                .endsWith("expected the text of <NAME> in room #1, found <B>"));
        assertTrue(refused("<HOUSE_ROOMS>stray<ROOM/></HOUSE_ROOMS>")
                .endsWith("expected <ROOM> or </HOUSE_ROOMS>, found the text 'stray'"));
        assertTrue(refused("<HOUSE_ROOMS><ROOM><NAME>A</NAME><NAME>B</NAME></ROOM></HOUSE_ROOMS>")
                .endsWith("<NAME> given twice in room #1"));
        assertTrue(refused("<HOUSE_ROOMS><ROOM id=\"1\"/></HOUSE_ROOMS>")
                .endsWith("<ROOM> has an attribute id; the house file has none"));
        assertTrue(refused("<h:HOUSE_ROOMS xmlns:h=\"urn:x\"/>").endsWith(
                "expected <HOUSE_ROOMS> as the root element, found <h:HOUSE_ROOMS (namespace urn:x; the house file uses none)>"));
    }

    @Test
    void aDoctypeIsRefusedSoNoEntityIsRead() {
        String xxe = refused("<?xml version=\"1.0\"?>\n<!DOCTYPE HOUSE_ROOMS [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>"
                + "\n<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>&x;</NAME></ROOM></HOUSE_ROOMS>");
        assertTrue(xxe.contains("a DOCTYPE is not allowed in a house file"), xxe);
        assertFalse(xxe.contains("root:"), "nothing of the file is read: " + xxe);
        String laughs = refused("<!DOCTYPE HOUSE_ROOMS [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;\">]>"
                + "<HOUSE_ROOMS><ROOM><NAME>&b;</NAME></ROOM></HOUSE_ROOMS>");
        assertTrue(laughs.contains("a DOCTYPE is not allowed in a house file"), laughs);
        assertTrue(refused("<!DOCTYPE HOUSE_ROOMS SYSTEM \"http://127.0.0.1:9/house.dtd\"><HOUSE_ROOMS/>")
                .contains("a DOCTYPE is not allowed"));
    }
}
