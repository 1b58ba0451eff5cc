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
        String roomToType = """
                Master Bedroom = Bedroom; Bedroom2 = Bedroom; WC = Bathroom; Toilet = Bathroom
                kitchen area = Kitchen; Living = Living room; TV room = Living room; Entrance = Hall
                Garden = Garden; Office = Office""";
        for (String pair : roomToType.replace("\n", "; ").split("; ")) {
            String[] kv = pair.split(" = ");
            assertEquals(kv[1], HouseFile.typeOf(kv[0]), "type of room " + kv[0] + " (a name without a type keeps its name)");
        }
    }

    @Test
    void writesOneRoomPerNameWithItsType(@TempDir Path dir) throws Exception {
        String xml = Files.readString(HouseFile.write(List.of("Living", "Bedroom2 & study"), dir.resolve("h.xml")));
        assertTrue(xml.contains("<NAME>Living</NAME>\n        <TYPE>Living room</TYPE>"), xml);
        assertTrue(xml.contains("<NAME>Bedroom2 &amp; study</NAME>\n        <TYPE>Bedroom</TYPE>"), xml);
    }
}
