package org.tinysep.simulator.flat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class FlatLoaderTest {

    @Test
    void flatAHasTheThesisNodesOverSixRooms() throws Exception {
        Flat flat = FlatLoader.load("flat-a");
        assertEquals(6, flat.house().rooms().size());
        assertEquals(20, flat.nodes().stream().filter(n -> n.family() == Family.AMICA).count());
        assertEquals(3, flat.nodes().stream().filter(n -> n.family() == Family.SUNSPOT && !n.has("person")).count());
        // and Anna's pendant (issue 26): a Sun SPOT person node she carries
        assertEquals("anna", flat.nodes().stream().filter(n -> n.has("person")).findFirst().orElseThrow().carriedBy());
        assertEquals(23, flat.withoutPersonNodes().nodes().size());
        assertEquals("Hall", flat.entrance().orElseThrow());
        for (String room : List.of("Hall", "Living Room", "Kitchen", "Bathroom", "Bedroom", "Study")) {
            assertTrue(flat.nodes().stream().anyMatch(n -> n.room().equals(room) && n.has("movement")), room + " movement");
        }
        assertEquals("rex", flat.nodes().stream().filter(n -> n.has("pet-collar")).findFirst().orElseThrow().carriedBy());
    }

    @Test
    void linksAreSymmetricAndPathsFollowThem() throws Exception {
        House house = FlatLoader.load("flat-a").house();
        for (Room r : house.rooms()) {
            for (String n : house.neighbours(r.name())) {
                assertTrue(house.neighbours(n).contains(r.name()), r.name() + " <-> " + n);
            }
        }
        assertEquals(List.of("Hall", "Living Room", "Kitchen"), house.path("Bathroom", "Kitchen"));
        assertEquals(List.of(), house.path("Study", "Study"));
        assertEquals("Living Room", house.roomName("living ROOM").orElseThrow());
    }

    private static House twoRooms() throws Exception {
        return House.read(new ByteArrayInputStream("""
                <HOUSE_ROOMS>
                  <ROOM><UID>a</UID><NAME>Hall</NAME><TYPE>Hall</TYPE><NEIGHBORS><ROOM_UID>b</ROOM_UID></NEIGHBORS></ROOM>
                  <ROOM><UID>b</UID><NAME>Kitchen</NAME><TYPE>Kitchen</TYPE><NEIGHBORS/></ROOM>
                </HOUSE_ROOMS>""".getBytes(StandardCharsets.UTF_8)), "test.xml");
    }

    @Test
    void aOneSidedLinkIsCompleted() throws Exception {
        assertEquals(List.of("Hall"), twoRooms().neighbours("Kitchen"));
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>X</NAME><TYPE>T</TYPE><NEIGHBORS><ROOM_UID>zz</ROOM_UID></NEIGHBORS></ROOM></HOUSE_ROOMS>; unknown neighbour zz",
            "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME></NAME><TYPE>T</TYPE></ROOM></HOUSE_ROOMS>; has no NAME",
            "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>X</NAME><TYPE>T</TYPE></ROOM><ROOM><UID>a</UID><NAME>Y</NAME><TYPE>T</TYPE></ROOM></HOUSE_ROOMS>; duplicate room UID a",
            "<!DOCTYPE x [<!ENTITY e SYSTEM 'file:///etc/passwd'>]><HOUSE_ROOMS/>; a DOCTYPE is not allowed",
            "<HOUSE_ROOMS><ROOM>; test.xml at line 1, column 20: bad XML",
            "<HOUSE_ROOMS><ROOM><UID>a</UID><FLOOR/></ROOM></HOUSE_ROOMS>; expected <UID>, <NAME>, <TYPE>, <NEIGHBORS> or </ROOM> in room #1, found <FLOOR>",
            "<ROOMS/>; expected <HOUSE_ROOMS> as the root element, found <ROOMS>"})
    void badHouseFilesAreRefusedClearly(String xml, String expected) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> House.read(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)), "test.xml"));
        assertTrue(e.getMessage().contains(expected) && e.getMessage().startsWith("test.xml"), e.getMessage());
    }

    @Test
    void aGoodLayoutParses() throws Exception {
        List<NodeSpec> nodes = NodeLayout.parse("""
                # comment
                door  | AmICA   | 2.7                 | door, movement | hall    | door=outer
                spot  | SunSPOT | 0014.4f01.0000.00ab | temperature    | KITCHEN |
                """, "nodes.txt", twoRooms());
        assertEquals(2, nodes.size());
        assertEquals(List.of("door", "movement"), nodes.get(0).types());
        assertTrue(nodes.get(0).outerDoor());
        assertEquals("0014.4F01.0000.00AB", nodes.get(1).address());
        assertEquals("Kitchen", nodes.get(1).room());
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "a | Zigbee | 1.1 | movement | Hall; unknown family 'Zigbee'",
            "a | AmICA | 1.999 | movement | Hall; 1.999",
            "a | AmICA | 1.0 | movement | Hall; platform's",
            "a | AmICA | 1.1 | toaster | Hall; unknown AMICA node type 'toaster'",
            "a | SunSPOT | 0014.4F01.0000.0001 | heater | Hall; unknown SUNSPOT node type 'heater'",
            "a | AmICA | 1.1 | movement | Attic; unknown room 'Attic'",
            "a | AmICA | 1.1 | movement; expected 'id | family",
            "a | AmICA | 1.1 | movement | Hall | door=outer; needs node type door",
            "a | AmICA | 1.1 | simple-light | Hall | colour=red; bad option 'colour=red'",
            "a | AmICA | 1.1 | simple-light | Hall | percent=140; percent must be 0..100"})
    void badLayoutLinesNameTheLine(String line, String expected) throws Exception {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> NodeLayout.parse("ok | AmICA | 1.2 | movement | Hall\n" + line, "nodes.txt", twoRooms()));
        assertTrue(e.getMessage().startsWith("nodes.txt:2: ") && e.getMessage().contains(expected), e.getMessage());
    }

    @Test
    void duplicateIdsAndAddressesAreRefused() throws Exception {
        House h = twoRooms();
        assertThrows(IllegalArgumentException.class, () -> NodeLayout.parse("a|AmICA|1.1|door|Hall\na|AmICA|1.2|door|Hall", "n", h));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> NodeLayout.parse("a|AmICA|1.1|door|Hall\nb|AmICA|1.1|door|Hall", "n", h));
        assertTrue(e.getMessage().contains("n:2: duplicate address 1.1"), e.getMessage());
    }
}
