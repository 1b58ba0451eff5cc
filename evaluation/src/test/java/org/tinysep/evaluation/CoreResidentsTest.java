package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;

import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.simulator.replay.Kind;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * Issue 28, session 36: the core replay reads a home of several residents as the platform does (the learn package's
 * {@code Residents}): a movement in a room where a seat mat is ON (its state from the whole recording, also from
 * before the replayed stretch) begins a sitting period. Residents not declared (0) are recognised from the history
 * (session 36b); a folder may declare them in a file {@code residents}.
 */
class CoreResidentsTest {

    private static final NodeSpec SEAT = new NodeSpec("Seat", NodeSpec.AMICA, AmicaAddress.parse("1.41"),
            AmicaNodeType.PRESENCE_SEAT, "Living Room", "", "Seat (Pressure)");
    private static final NodeSpec PIR = new NodeSpec("Door Living", NodeSpec.AMICA, AmicaAddress.parse("1.40"),
            AmicaNodeType.MOVEMENT, "Living Room", "", "Living door (PIR)");
    private static final LocalDateTime T = LocalDateTime.parse("2012-11-22T15:09:00");
    private static final List<SensorEvent> EVENTS = List.of(
            new SensorEvent(T.minusHours(1), "Seat", "Living", Kind.PRESSURE, false),
            new SensorEvent(T, "Seat", "Living", Kind.PRESSURE, true),
            new SensorEvent(T.plusMinutes(18), "Door Living", "Living", Kind.MOTION, true),
            new SensorEvent(T.plusMinutes(77), "Seat", "Living", Kind.PRESSURE, false),
            new SensorEvent(T.plusMinutes(80), "Door Living", "Living", Kind.MOTION, true));

    private static List<Boolean> seated(int residents, List<SensorEvent> stretch) {
        Home h = new Home("test", EVENTS, List.of(), null, null, List.of(SEAT, PIR), residents);
        return new CoreReplay(h, true).acts(stretch).stream().map(CoreReplay.Act::sighting).map(Sighting::seated)
                .toList();
    }

    @Test
    void aMovementWhileASeatMatIsOnIsSittingInAHomeOfTwo() {
        assertEquals(List.of(true, true, false, false), seated(2, EVENTS.subList(1, EVENTS.size())),
                "seat ON, movement with the seat ON (sitting), seat OFF, movement");
        assertEquals(List.of(true, false), seated(2, EVENTS.subList(2, 4)),
                "a stretch that starts after the seat turned ON knows it is ON");
    }

    @Test
    void oneResidentIsReadAsBefore() {
        assertEquals(List.of(true, false, false, false), seated(1, EVENTS.subList(1, EVENTS.size())));
    }

    @Test
    void theTwoResidentHomeDeclaresTwoOnlyWhenItsHomesDeclareTheirs() {
        Home host = new Home("h", EVENTS, List.of(), Path.of("m"), Path.of("h.xml"), List.of(SEAT, PIR));
        assertEquals(0, host.residents(), "nobody declares them: recognised from the history");
        assertEquals(0, Variants.apply("two", host, host).residents());
        Home one = host.withResidents(1);
        assertEquals(2, Variants.apply("two", one, one).residents());
        assertEquals(1, Variants.apply("nomotion", one, one).residents());
    }

    @Test
    void aFolderDeclaresItsResidentsInAnOptionalFile(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("residents");
        assertEquals(0, Home.residents(f), "no file: recognised from the history");
        Files.writeString(f, "# people living here\n2\n");
        assertEquals(2, Home.residents(f));
        Files.writeString(f, "two\n");
        IOException e = assertThrows(IOException.class, () -> Home.residents(f));
        assertTrue(e.getMessage().contains("must hold one whole number"), e.getMessage());
    }
}
