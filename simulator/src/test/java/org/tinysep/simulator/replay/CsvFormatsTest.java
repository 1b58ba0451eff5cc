package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** events.csv and labels.csv exactly as simulator/README-replay.md specifies them. */
class CsvFormatsTest {

    @TempDir
    Path tmp;

    @Test
    void readsEventsWithFractionalSecondsCrlfAndBothValueStyles() throws Exception {
        Path f = tmp.resolve("events.csv");
        Files.writeString(f, "time_iso,sensor,room,kind,value\r\n"
                + "2020-01-01T07:00:00,Hall PIR,Hall,motion,ON\r\n"
                + "2020-01-01T07:00:00.250,Front,Hall,door,OPEN\r\n\r\n"
                + "2020-01-01T07:00:05,Front,Hall,door,CLOSE\r\n"
                + "2020-01-01T07:01:00,Kettle,,other,off\r\n");
        List<SensorEvent> events = EventsCsv.read(f);
        assertEquals(4, events.size());
        assertEquals(new SensorEvent(LocalDateTime.parse("2020-01-01T07:00:00.250"), "Front", "Hall", Kind.DOOR, true),
                events.get(1));
        assertEquals(new SensorEvent(LocalDateTime.parse("2020-01-01T07:01"), "Kettle", "", Kind.OTHER, false),
                events.get(3));
    }

    @Test
    void writerUsesOpenCloseForDoorsAndAlwaysWritesSeconds() throws Exception {
        Path f = tmp.resolve("out.csv");
        EventsCsv.write(List.of(
                new SensorEvent(LocalDateTime.parse("2020-01-01T07:00"), "Front", "Hall", Kind.DOOR, true),
                new SensorEvent(LocalDateTime.parse("2020-01-01T07:00:01.5"), "Bed", "Bedroom", Kind.PRESSURE, false)), f);
        assertEquals(List.of("time_iso,sensor,room,kind,value", "2020-01-01T07:00:00,Front,Hall,door,OPEN",
                "2020-01-01T07:00:01.5,Bed,Bedroom,pressure,OFF"), Files.readAllLines(f));
        assertThrows(IllegalArgumentException.class, () -> EventsCsv.write(List.of(
                new SensorEvent(LocalDateTime.parse("2020-01-01T07:00"), "a,b", "Hall", Kind.DOOR, true)), f));
    }

    @Test
    void badEventRowsNameFileAndLine() {
        assertEventError("events.csv:1: expected the header", "time,sensor,room,kind,value");
        assertEventError("events.csv:2: expected 5 comma-separated fields", HEADER_LINE, "2020-01-01T07:00:00,a,b,motion");
        assertEventError("events.csv:2: bad time '2020-01-01 07:00:00'", HEADER_LINE, "2020-01-01 07:00:00,a,b,motion,ON");
        assertEventError("events.csv:2: unknown sensor kind 'sonar'", HEADER_LINE, "2020-01-01T07:00:00,a,b,sonar,ON");
        assertEventError("events.csv:2: bad value 'MAYBE'", HEADER_LINE, "2020-01-01T07:00:00,a,b,motion,MAYBE");
        assertEventError("events.csv:2: sensor name is empty", HEADER_LINE, "2020-01-01T07:00:00,,b,motion,ON");
        assertEventError("events.csv:3: time 2020-01-01T06:59:59 is earlier", HEADER_LINE,
                "2020-01-01T07:00:00,a,b,motion,ON", "2020-01-01T06:59:59,a,b,motion,OFF");
    }

    @Test
    void labelsRoundTripAndErrors() throws Exception {
        Path f = tmp.resolve("labels.csv");
        List<Label> labels = List.of(
                new Label(LocalDateTime.parse("2020-01-01T08:00"), LocalDateTime.parse("2020-01-01T09:30:15"), "Leaving", "anna"),
                new Label(LocalDateTime.parse("2020-01-01T10:00"), LocalDateTime.parse("2020-01-01T09:00"), "Snack", ""));
        LabelsCsv.write(labels, f);
        assertEquals(labels, LabelsCsv.read(f));
        ReplayFormatException e = assertThrows(ReplayFormatException.class, () -> LabelsCsv.parse(
                List.of(LabelsCsv.HEADER, "2020-01-01T08:00,2020-01-01T09:00,,x"), "labels.csv"));
        assertEquals("labels.csv:2: activity is empty", e.getMessage());
        e = assertThrows(ReplayFormatException.class, () -> LabelsCsv.parse(List.of("start,end"), "labels.csv"));
        assertTrue(e.getMessage().startsWith("labels.csv:1: expected the header"), e.getMessage());
    }

    private static final String HEADER_LINE = EventsCsv.HEADER;

    private static void assertEventError(String prefix, String... lines) {
        ReplayFormatException e = assertThrows(ReplayFormatException.class,
                () -> EventsCsv.parse(List.of(lines), "events.csv"));
        assertTrue(e.getMessage().startsWith(prefix), e.getMessage());
    }
}
