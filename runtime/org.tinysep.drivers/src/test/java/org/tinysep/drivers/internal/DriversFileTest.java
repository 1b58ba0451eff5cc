package org.tinysep.drivers.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class DriversFileTest {

    private static final Instant NOW = Instant.parse("2026-11-22T14:00:00Z");

    @TempDir
    Path dir;

    @Test
    void roundTripsTheThesisShapeAndSkipsUnchangedWrites() throws Exception {
        DriversFile f = new DriversFile(dir.resolve("drivers.xml"), new DriversCodec());
        List<DriverEntry> entries = List.of(new DriverEntry("bundles/5-apps/door.jar", "org.tinysep.amica.door", true,
                "ACTIVE"), new DriverEntry("file:/x/y.jar", "", false, "DISABLED"));
        assertTrue(f.save(entries));
        String xml = Files.readString(f.path());
        assertTrue(xml.contains("<DRIVERS_LIST>") && xml.contains("<FILE_PATH>bundles/5-apps/door.jar</FILE_PATH>")
                && xml.contains("<FULL_NAME>org.tinysep.amica.door</FULL_NAME>") && xml.contains("<STATUS>ACTIVE</STATUS>"),
                xml);
        assertFalse(f.save(entries), "same content: no write");
        assertEquals(entries, new DriversFile(f.path(), new DriversCodec()).read(NOW));
    }

    @Test
    void thesisFileWithoutEnabledMeansEnabled() throws Exception {
        Path p = dir.resolve("drivers.xml");
        Files.writeString(p, "<DRIVERS_LIST><DRIVER><FILE_PATH>../../dlls/BusRadioAmica.dll</FILE_PATH>"
                + "<FULL_NAME>BusRadioAmica.CDriverBusRadioAmica</FULL_NAME><STATUS>IN_USE</STATUS></DRIVER></DRIVERS_LIST>");
        DriverEntry e = new DriversFile(p, new DriversCodec()).read(NOW).get(0);
        assertTrue(e.enabled());
        assertEquals("BusRadioAmica.CDriverBusRadioAmica", e.symbolicName());
    }

    @Test
    void brokenFileIsMovedAsideWithAClearMessage() throws Exception {
        Path p = dir.resolve("drivers.xml");
        Files.writeString(p, "<DRIVERS_LIST><DRIVER><FILE_PATH>a.jar</FILE_PATH>\n<DRIVER></DRIVERS_LIST>");
        MalformedDriversException e = assertThrows(MalformedDriversException.class,
                () -> new DriversFile(p, new DriversCodec()).read(NOW));
        assertTrue(e.getMessage().startsWith("drivers.xml: bad XML: line 2"), e.getMessage());
        assertTrue(e.getMessage().endsWith("moved aside to drivers.xml.broken-20261122-140000"), e.getMessage());
        assertFalse(Files.exists(p));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of("drivers.xml.broken-20261122-140000"),
                    files.map(f -> f.getFileName().toString()).toList());
        }
    }

    @Test
    void entryWithoutFileOrRepeatedNameIsRejected() throws Exception {
        Path p = dir.resolve("drivers.xml");
        Files.writeString(p, "<DRIVERS_LIST><DRIVER><FULL_NAME>a</FULL_NAME></DRIVER></DRIVERS_LIST>");
        assertTrue(assertThrows(MalformedDriversException.class, () -> new DriversFile(p, new DriversCodec()).read(NOW))
                .getMessage().contains("DRIVER #1 has no FILE_PATH"));
        Files.writeString(p, "<DRIVERS_LIST><DRIVER><FILE_PATH>a.jar</FILE_PATH><FULL_NAME>a</FULL_NAME></DRIVER>"
                + "<DRIVER><FILE_PATH>b.jar</FILE_PATH><FULL_NAME>a</FULL_NAME></DRIVER></DRIVERS_LIST>");
        assertTrue(assertThrows(MalformedDriversException.class, () -> new DriversFile(p, new DriversCodec()).read(NOW))
                .getMessage().contains("DRIVER #2 repeats a"));
    }

    @Test
    void externalEntitiesAreRefused() throws Exception {
        Path secret = Files.writeString(dir.resolve("secret.txt"), "s3cret");
        Path p = dir.resolve("drivers.xml");
        Files.writeString(p, "<?xml version=\"1.0\"?><!DOCTYPE d [<!ENTITY x SYSTEM \"" + secret.toUri() + "\">]>"
                + "<DRIVERS_LIST><DRIVER><FILE_PATH>&x;</FILE_PATH></DRIVER></DRIVERS_LIST>");
        assertThrows(MalformedDriversException.class, () -> new DriversFile(p, new DriversCodec()).read(NOW));
    }
}
