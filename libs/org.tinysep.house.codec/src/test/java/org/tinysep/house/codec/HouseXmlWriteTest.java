package org.tinysep.house.codec;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.repo.RepoFiles;
import org.xml.sax.SAXException;

/**
 * The writer gives the bytes House Information's JAXB marshaller wrote: {@code written-by-jaxb/} holds its output
 * (captured from the JAXB codec before it was removed) for the thesis example, flat A, an empty house and odd text.
 */
class HouseXmlWriteTest {

    static byte[] jaxb(String name) throws IOException {
        try (InputStream in = HouseXmlWriteTest.class.getResourceAsStream("/written-by-jaxb/" + name)) {
            return in.readAllBytes();
        }
    }

    @Test
    void writesWhatJaxbWroteForTheCommittedFlats() throws Exception {
        byte[] fig37 = java.nio.file.Files.readAllBytes(RepoFiles.require("bundles", "services", "org.tinysep.houseinformation",
                "src", "test", "resources", "fig-3-7-house.xml"));
        assertEquals(new String(jaxb("fig37.xml"), StandardCharsets.UTF_8),
                HouseXml.toString(HouseXml.read(fig37, "fig 3.7")));
        byte[] flatA = java.nio.file.Files.readAllBytes(RepoFiles.require("simulator", "src", "main", "resources",
                "flats", "flat-a", "house.xml"));
        assertArrayEquals(jaxb("flat-a.xml"), HouseXml.toBytes(HouseXml.read(flatA, "flat-a")));
        assertArrayEquals(jaxb("empty.xml"), HouseXml.toBytes(HouseRooms.EMPTY));
    }

    @Test
    void escapesAsJaxbDidAndReadsBackTheSameText() throws Exception {
        HouseRooms odd = new HouseRooms(List.of(
                new HouseRoom("u-1", "Bed & <Study> \"q\" 'a' ü € \uD83D\uDE00 ]]> tab\there", "Type > x", List.of("u-2")),
                new HouseRoom("u-2", "Lone\r\nline", "Hall", List.of("u-1")),
                new HouseRoom("u-3", "Alone", "Hall", List.of())));
        byte[] written = HouseXml.toBytes(odd);
        assertEquals(new String(jaxb("special.xml"), StandardCharsets.UTF_8), new String(written, StandardCharsets.UTF_8));
        assertEquals(odd, HouseXml.read(written, "written"));
    }

    @Test
    void aCharacterXmlCannotCarryIsNamed() {
        HouseRooms bad = new HouseRooms(List.of(new HouseRoom("u-1", "Bell\u0007", "Hall", List.of())));
        assertEquals("room #1 (UID u-1): NAME holds the character U+0007, which an XML file cannot carry",
                assertThrows(IllegalArgumentException.class, () -> HouseXml.toBytes(bad)).getMessage());
    }

    @Test
    void whatIsWrittenPassesTheBackupRestoresSchema() throws Exception {
        Schema xsd = SchemaFactory.newDefaultInstance().newSchema(RepoFiles.require("runtime", "org.tinysep.runtime",
                "src", "main", "resources", "org", "tinysep", "runtime", "internal", "backup", "house.xsd").toFile());
        for (String name : List.of("fig37.xml", "flat-a.xml", "empty.xml", "special.xml")) {
            byte[] written = HouseXml.toBytes(HouseXml.read(jaxb(name), name));
            xsd.newValidator().validate(new StreamSource(new ByteArrayInputStream(written)));
        }
        byte[] unknownNeighbour = HouseXml.toBytes(new HouseRooms(List.of(new HouseRoom("a", "A", "T", List.of("zz")))));
        assertThrows(SAXException.class, () -> xsd.newValidator().validate(
                new StreamSource(new ByteArrayInputStream(unknownNeighbour))), "the schema check can fail");
    }
}
