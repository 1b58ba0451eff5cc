package org.tinysep.drivers.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The StAX codec of drivers.xml (issue 29: no JAXB context on the start path). */
class DriversCodecTest {

    /** A list as the JAXB codec of earlier builds wrote it (formatted output, standalone="yes"). */
    private static final String WRITTEN_BY_JAXB = """
            <?xml version="1.0" encoding="UTF-8" standalone="yes"?>
            <DRIVERS_LIST>
                <DRIVER>
                    <FILE_PATH>bundles/5-apps/door.jar</FILE_PATH>
                    <FULL_NAME>org.tinysep.amica.door</FULL_NAME>
                    <ENABLED>true</ENABLED>
                    <STATUS>ACTIVE</STATUS>
                </DRIVER>
                <DRIVER>
                    <FILE_PATH>bundles/5-apps/a &amp; b.jar</FILE_PATH>
                    <ENABLED>false</ENABLED>
                </DRIVER>
            </DRIVERS_LIST>
            """;

    private final DriversCodec codec = new DriversCodec();

    @Test
    void readsWhatTheJaxbCodecWroteAndWritesTheSameLayout() throws Exception {
        List<DriverEntry> entries = codec.read(WRITTEN_BY_JAXB.getBytes(StandardCharsets.UTF_8), "drivers.xml");
        assertEquals(List.of(new DriverEntry("bundles/5-apps/door.jar", "org.tinysep.amica.door", true, "ACTIVE"),
                new DriverEntry("bundles/5-apps/a & b.jar", "", false, "")), entries);
        String written = new String(codec.write(entries), StandardCharsets.UTF_8);
        assertEquals(WRITTEN_BY_JAXB.replace(" standalone=\"yes\"", ""), written);
        assertEquals(entries, codec.read(codec.write(entries), "drivers.xml"));
    }

    @Test
    void unknownElementsAreMalformedAndAnEmptyListRoundTrips() throws Exception {
        String xml = "<DRIVERS_LIST><DRIVER><FILE_PATH>x.jar</FILE_PATH>\n<COMMENT>a</COMMENT></DRIVER></DRIVERS_LIST>";
        MalformedDriversException e = assertThrows(MalformedDriversException.class,
                () -> codec.read(xml.getBytes(StandardCharsets.UTF_8), "drivers.xml"));
        assertTrue(e.getMessage().startsWith("drivers.xml: bad XML: line 2") && e.getMessage().contains("<COMMENT>"),
                e.getMessage());
        assertEquals(List.of(), codec.read(codec.write(List.of()), "drivers.xml"));
    }

    @Test
    void aWrongRootOrEnabledValueIsMalformedWithAClearMessage() {
        MalformedDriversException root = assertThrows(MalformedDriversException.class,
                () -> codec.read("<HOUSE/>".getBytes(StandardCharsets.UTF_8), "drivers.xml"));
        assertTrue(root.getMessage().startsWith("drivers.xml: bad XML: line 1") && root.getMessage().contains("<HOUSE>"),
                root.getMessage());
        MalformedDriversException enabled = assertThrows(MalformedDriversException.class, () -> codec.read(
                "<DRIVERS_LIST><DRIVER><FILE_PATH>a.jar</FILE_PATH><ENABLED>yes</ENABLED></DRIVER></DRIVERS_LIST>"
                        .getBytes(StandardCharsets.UTF_8), "drivers.xml"));
        assertEquals("drivers.xml: DRIVER #1 has ENABLED 'yes' (true or false)", enabled.getMessage());
        assertFalse(enabled.getMessage().contains("Exception"));
    }
}
