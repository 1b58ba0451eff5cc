package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Atomic saves, the .bak, and the malformed-file policy: the last good house is never wiped. */
class HouseFileTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    @TempDir
    Path dir;

    private final HouseCodec codec = new HouseCodec();

    private HouseFile file() {
        return new HouseFile(dir.resolve("house.xml"), codec);
    }

    private HousePlan good() throws Exception {
        return codec.read(HouseCodecTest.fig37(), "fig");
    }

    @Test
    void noFileIsAnEmptyHouseNotAnError() throws Exception {
        HouseFile.Load l = file().load(T0);
        assertEquals(List.of(), l.plan().rooms());
        assertNull(l.problem());
        assertEquals(List.of(), names());
    }

    @Test
    void saveKeepsThePreviousFileAsBak() throws Exception {
        HouseFile f = file();
        HousePlan one = good();
        f.save(one);
        assertEquals(List.of("house.xml"), names());
        HousePlan two = one.without(HouseCodecTest.KITCHEN);
        f.save(two);
        assertEquals(List.of("house.xml", "house.xml.bak"), names());
        assertArrayEquals(codec.write(one), Files.readAllBytes(dir.resolve("house.xml.bak")));
        assertEquals(two.rooms(), f.load(T0).plan().rooms());
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>A</NAME>",
        "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>A</NAME><TYPE>T</TYPE><NEIGHBORS><ROOM_UID>nope</ROOM_UID></NEIGHBORS></ROOM></HOUSE_ROOMS>",
        "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME>A</NAME><TYPE>T</TYPE></ROOM><ROOM><UID>a</UID><NAME>B</NAME><TYPE>T</TYPE></ROOM></HOUSE_ROOMS>",
        "<HOUSE_ROOMS><ROOM><UID>a</UID><NAME></NAME><TYPE>T</TYPE></ROOM></HOUSE_ROOMS>"})
    void aMalformedFileIsMovedAsideAndTheLastGoodHouseUsed(String broken) throws Exception {
        HouseFile f = file();
        HousePlan one = good();
        f.save(one);
        f.save(one.without(HouseCodecTest.KITCHEN)); // .bak = the full house
        Files.writeString(dir.resolve("house.xml"), broken);

        HouseFile.Load l = f.load(T0);
        assertEquals(one.rooms(), l.plan().rooms(), "the last good house, from the .bak");
        assertTrue(l.problem().startsWith(dir.resolve("house.xml").toString()), l.problem());
        assertTrue(l.problem().contains("moved aside to house.xml.broken-20261122-100000"), l.problem());
        assertEquals(broken, Files.readString(dir.resolve("house.xml.broken-20261122-100000")));
        assertEquals(List.of("house.xml", "house.xml.bak", "house.xml.broken-20261122-100000"), names());
        assertArrayEquals(codec.write(one), Files.readAllBytes(dir.resolve("house.xml")), "written back");
        assertArrayEquals(codec.write(one), Files.readAllBytes(dir.resolve("house.xml.bak")), "never wiped");
    }

    @Test
    void aMalformedFileWithoutBackupGivesAnEmptyHouseAndKeepsTheFile() throws Exception {
        Files.writeString(dir.resolve("house.xml"), "not xml at all");
        HouseFile.Load l = file().load(T0);
        assertEquals(List.of(), l.plan().rooms());
        assertTrue(l.problem().endsWith("no house.xml.bak: starting with an empty house"), l.problem());
        assertEquals(List.of("house.xml.broken-20261122-100000"), names());
        Files.writeString(dir.resolve("house.xml"), "still not xml");
        file().load(T0);
        assertEquals(List.of("house.xml.broken-20261122-100000", "house.xml.broken-20261122-100000-2"), names());
    }

    @Test
    void aWriteThatFailsBeforeTheRenameLeavesTheOldFileAndNoTempFile() throws Exception {
        HouseFile f = file();
        HousePlan one = good();
        f.save(one);
        byte[] before = Files.readAllBytes(dir.resolve("house.xml"));
        f.beforeRename = () -> {
            throw new UncheckedIOException(new IOException("power cut"));
        };
        assertThrows(UncheckedIOException.class, () -> f.save(one.without(HouseCodecTest.BATHROOM)));
        assertArrayEquals(before, Files.readAllBytes(dir.resolve("house.xml")));
        assertTrue(names().stream().noneMatch(n -> n.endsWith(".tmp")), names().toString());
        f.beforeRename = () -> { };
        assertEquals(one.rooms(), f.load(T0).plan().rooms());
    }

    @Test
    void aFileThatCouldNotBeLoadedNeverBecomesTheBackup() throws Exception {
        HouseFile f = file();
        HousePlan one = good();
        f.save(one);
        f.save(one.without(HouseCodecTest.KITCHEN)); // .bak = the full house
        byte[] lastGood = Files.readAllBytes(dir.resolve("house.xml.bak"));
        HouseFile restarted = file(); // a new start that never managed to load the file
        Files.writeString(dir.resolve("house.xml"), "garbage written by someone else");
        restarted.save(HousePlan.EMPTY);
        assertArrayEquals(lastGood, Files.readAllBytes(dir.resolve("house.xml.bak")));
        assertTrue(names().stream().anyMatch(n -> n.startsWith("house.xml.broken-")), names().toString());
    }

    private List<String> names() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    static String text(Path p) throws IOException {
        return new String(Files.readAllBytes(p), StandardCharsets.UTF_8);
    }
}
