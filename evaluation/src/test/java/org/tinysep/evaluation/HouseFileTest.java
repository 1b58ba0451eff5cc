package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A recorded home without a house file gets one whose room types come from the room names. */
class HouseFileTest {

    @Test
    void roomTypesFromNames() {
        assertEquals("Bedroom", HouseFile.typeOf("Master Bedroom"));
        assertEquals("Bedroom", HouseFile.typeOf("Bedroom2"));
        assertEquals("Bathroom", HouseFile.typeOf("WC"));
        assertEquals("Bathroom", HouseFile.typeOf("Toilet"));
        assertEquals("Kitchen", HouseFile.typeOf("kitchen area"));
        assertEquals("Living room", HouseFile.typeOf("Living"));
        assertEquals("Living room", HouseFile.typeOf("TV room"));
        assertEquals("Hall", HouseFile.typeOf("Entrance"));
        assertEquals("Garden", HouseFile.typeOf("Garden"), "no type in the name: the name itself (default limit)");
        assertEquals("Office", HouseFile.typeOf("Office"));
    }

    @Test
    void writesOneRoomPerNameWithItsType(@TempDir Path dir) throws Exception {
        String xml = Files.readString(HouseFile.write(List.of("Living", "Bedroom2 & study"), dir.resolve("h.xml")));
        assertTrue(xml.contains("<NAME>Living</NAME>\n        <TYPE>Living room</TYPE>"), xml);
        assertTrue(xml.contains("<NAME>Bedroom2 &amp; study</NAME>\n        <TYPE>Bedroom</TYPE>"), xml);
    }
}
