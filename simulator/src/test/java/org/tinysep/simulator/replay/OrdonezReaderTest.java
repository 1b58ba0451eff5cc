package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Hand-made Ordonez-format input: whitespace, CRs, naming of ambiguous sensors and clear errors. */
class OrdonezReaderTest {

    private static final String H1 = "Start time          \tEnd time            \tLocation\tType\t\tPlace\r";
    private static final String H2 = "--------------------\t--------------------\t--------\t--------\t-----\r";

    @Test
    void irregularWhitespaceCrAndBlankLinesAreAccepted() throws Exception {
        List<SensorEvent> events = OrdonezReader.parseSensors(List.of(H1, H2,
                "2011-11-28 10:21:44\t\t2011-11-28 10:23:31\t\tBasin\t\tPIR\t\t\tBathroom\r",
                "2011-11-28 10:21:24 \t2011-11-28 10:21:31  Cabinet \tMagnetic\tBathroom\t\r",
                "", "   \t\r"), "s.txt");
        assertEquals(4, events.size());
        assertEquals(new SensorEvent(java.time.LocalDateTime.parse("2011-11-28T10:21:24"), "Cabinet", "Bathroom",
                Kind.DOOR, true), events.get(0), "sorted by time, not file order");
        assertEquals(List.of(true, false, true, false), events.stream().map(SensorEvent::on).toList());
        assertEquals(Kind.MOTION, events.get(2).kind());
        assertEquals(List.of("Cabinet", "Cabinet", "Basin", "Basin"), events.stream().map(SensorEvent::sensor).toList());
    }

    @Test
    void sameLocationInSeveralPlacesIsNamedByPlace() throws Exception {
        List<SensorEvent> events = OrdonezReader.parseSensors(List.of(H1, H2,
                "2012-11-12 00:22:57\t\t2012-11-12 00:22:59\t\tDoor\t\tPIR\t\t\tLiving",
                "2012-11-12 00:23:14\t\t2012-11-12 00:23:17\t\tDoor\t\tPIR\t\t\tKitchen",
                "2012-11-12 00:24:14\t\t2012-11-12 00:24:17\t\tMicro wave\t\tElectric\tKitchen"), "b.txt");
        assertEquals(List.of("Door Living", "Door Living", "Door Kitchen", "Door Kitchen", "Micro wave", "Micro wave"),
                events.stream().map(SensorEvent::sensor).toList());
    }

    @Test
    void zeroLengthIntervalKeepsOnBeforeOff() throws Exception {
        List<SensorEvent> events = OrdonezReader.parseSensors(List.of(H1, H2,
                "2011-11-28 10:00:00\t2011-11-28 10:00:00\tSeat\tPressure\tLiving"), "s.txt");
        assertEquals(List.of(true, false), events.stream().map(SensorEvent::on).toList());
    }

    @Test
    void malformedRowsNameFileAndLine() {
        assertMessage("s.txt:1: not an Ordonez file", List.of("hello", "world"));
        assertMessage("s.txt:3: expected 'start end location type place'",
                List.of(H1, H2, "2011-11-28 10:21:44\t2011-11-28 10:23:31\tBasin\tPIR"));
        assertMessage("s.txt:4: bad time '2011-11-28 25:21:44'", List.of(H1, H2,
                "2011-11-28 10:21:44\t2011-11-28 10:23:31\tBasin\tPIR\tBathroom",
                "2011-11-28 25:21:44\t2011-11-28 10:23:31\tBasin\tPIR\tBathroom"));
        assertMessage("s.txt:3: unknown sensor type 'Sonar'",
                List.of(H1, H2, "2011-11-28 10:21:44\t2011-11-28 10:23:31\tBasin\tSonar\tBathroom"));
        assertMessage("s.txt:3: interval ends",
                List.of(H1, H2, "2011-11-28 10:21:44\t2011-11-28 10:20:31\tBasin\tPIR\tBathroom"));
    }

    @Test
    void labelsKeepMultiWordActivitiesAndImproperIntervals() throws Exception {
        List<Label> labels = OrdonezReader.parseLabels(List.of("Start time\tEnd time\tActivity\t\r", "-----\r",
                "2011-11-28 10:51:41\t\t2011-11-28 13:05:07\t\tSpare_Time/TV\t\t\r",
                "2011-12-01 19:28:51\t\t2011-12-01 16:29:59\t\tToileting\t\r", "\r"), "a.txt");
        assertEquals(2, labels.size());
        assertEquals("Spare_Time/TV", labels.get(0).activity());
        assertEquals("", labels.get(0).resident());
        assertTrue(labels.get(0).isProper());
        assertTrue(!labels.get(1).isProper());
        ReplayFormatException e = assertThrows(ReplayFormatException.class, () -> OrdonezReader.parseLabels(
                List.of("Start time", "----", "2011-11-28 10:51:41\t2011-11-28 13:05:07"), "a.txt"));
        assertTrue(e.getMessage().startsWith("a.txt:3: expected 'start end activity'"), e.getMessage());
    }

    private static void assertMessage(String prefix, List<String> lines) {
        ReplayFormatException e = assertThrows(ReplayFormatException.class,
                () -> OrdonezReader.parseSensors(lines, "s.txt"));
        assertTrue(e.getMessage().startsWith(prefix), e.getMessage());
    }
}
