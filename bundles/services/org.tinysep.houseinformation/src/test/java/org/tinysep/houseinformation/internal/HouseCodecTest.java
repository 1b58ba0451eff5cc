package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.Room;

/** The thesis Figure 3.7 format, read and written through the house codec. */
class HouseCodecTest {

    static final String BEDROOM = "decb2a7f-88e6-4238-9d09-9fc2e932d4ec";
    static final String BATHROOM = "0cf52171-0d00-486f-bbb2-e6ef950012b5";
    static final String KITCHEN = "9ffbd81c-9ab3-4bf7-8b13-8ab31634ebf5";

    private final HouseCodec codec = new HouseCodec();

    static byte[] fig37() throws IOException {
        try (InputStream in = HouseCodecTest.class.getResourceAsStream("/fig-3-7-house.xml")) {
            return in.readAllBytes();
        }
    }

    @Test
    void theThesisExampleParses() throws Exception {
        HousePlan plan = codec.read(fig37(), "fig 3.7");
        assertEquals(List.of(new Room(BEDROOM, "Master Bedroom", "Bedroom", Set.of(BATHROOM, KITCHEN)),
                new Room(BATHROOM, "Bathroom", "Bathroom", Set.of(BEDROOM)),
                new Room(KITCHEN, "Kitchen", "Kitchen", Set.of(BEDROOM))), plan.rooms());
    }

    @Test
    void roundTripIsByteStable() throws Exception {
        byte[] first = codec.write(codec.read(fig37(), "fig 3.7"));
        byte[] second = codec.write(codec.read(first, "written"));
        assertArrayEquals(first, second);
        String text = new String(first, StandardCharsets.UTF_8);
        assertTrue(text.contains("<NEIGHBORS>\n            <ROOM_UID>" + BATHROOM + "</ROOM_UID>\n            <ROOM_UID>"
                + KITCHEN + "</ROOM_UID>"), "neighbours in plan order, like the thesis: " + text);
        assertEquals(codec.read(fig37(), "a").rooms(), codec.read(first, "b").rooms());
    }

    @Test
    void aHalfLinkIsCompletedOnTheOtherSide() throws Exception {
        String xml = "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>A</NAME><TYPE>Hall</TYPE><NEIGHBORS><ROOM_UID>b</ROOM_UID>"
                + "</NEIGHBORS></ROOM><ROOM><UID>b</UID><NAME>B</NAME><TYPE>Hall</TYPE></ROOM></HOUSE_ROOMS>";
        HousePlan plan = codec.read(xml.getBytes(StandardCharsets.UTF_8), "x");
        assertEquals(Set.of("a"), plan.existing("b").neighbours());
    }

    @Test
    void badXmlIsReportedWithLineAndColumn() {
        byte[] xml = "<HOUSE_ROOMS>\n<ROOM>\n  <UID>a</UID>\n  <NAME>A</NAM>\n</ROOM></HOUSE_ROOMS>"
                .getBytes(StandardCharsets.UTF_8);
        MalformedHouseException e = assertThrows(MalformedHouseException.class, () -> codec.read(xml, "h.xml"));
        assertTrue(e.getMessage().startsWith("h.xml at line 4, column "), e.getMessage());
        assertTrue(e.getMessage().contains("bad XML"), e.getMessage());
    }

    @Test
    void semanticProblemsAreNamed() {
        assertEquals("x: room #2 (UID a): duplicate UID a", problem(
                "<ROOM><UID>a</UID><NAME>A</NAME><TYPE>T</TYPE></ROOM><ROOM><UID>a</UID><NAME>B</NAME><TYPE>T</TYPE></ROOM>"));
        assertEquals("x: room #1 (UID a): blank NAME", problem("<ROOM><UID>a</UID><NAME> </NAME><TYPE>T</TYPE></ROOM>"));
        assertEquals("x: room #1 (UID a): blank TYPE", problem("<ROOM><UID>a</UID><NAME>A</NAME></ROOM>"));
        assertEquals("x: room #1 has no UID", problem("<ROOM><NAME>A</NAME><TYPE>T</TYPE></ROOM>"));
        assertEquals("x: room a (A): unknown neighbour UID zz", problem(
                "<ROOM><UID>a</UID><NAME>A</NAME><TYPE>T</TYPE><NEIGHBORS><ROOM_UID>zz</ROOM_UID></NEIGHBORS></ROOM>"));
        assertEquals("x: room a (A) is its own neighbour", problem(
                "<ROOM><UID>a</UID><NAME>A</NAME><TYPE>T</TYPE><NEIGHBORS><ROOM_UID>a</ROOM_UID></NEIGHBORS></ROOM>"));
    }

    @Test
    void doctypesAreRefused() {
        byte[] xml = ("<?xml version=\"1.0\"?><!DOCTYPE HOUSE_ROOMS [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>"
                + "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>&x;</NAME><TYPE>T</TYPE></ROOM></HOUSE_ROOMS>")
                .getBytes(StandardCharsets.UTF_8);
        assertThrows(MalformedHouseException.class, () -> codec.read(xml, "evil"));
    }

    private String problem(String rooms) {
        byte[] xml = ("<HOUSE_ROOMS>" + rooms + "</HOUSE_ROOMS>").getBytes(StandardCharsets.UTF_8);
        return assertThrows(MalformedHouseException.class, () -> codec.read(xml, "x")).getMessage();
    }
}
