package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.simulator.replay.Kind;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.SensorEvent;

/** The derived homes: a second resident living through the whole host recording, and a home without motion. */
class VariantsTest {

    private static final NodeSpec SEAT = new NodeSpec("Seat", NodeSpec.AMICA, AmicaAddress.parse("1.41"),
            AmicaNodeType.PRESENCE_SEAT, "Living Room", "", "Seat (Pressure)");
    private static final NodeSpec PIR = new NodeSpec("Motion", NodeSpec.AMICA, AmicaAddress.parse("1.40"),
            AmicaNodeType.MOVEMENT, "Living Room", "", "Living (PIR)");

    /** {@code days} days from {@code from}, a seat and a motion event every {@code hours} hours. */
    private static Home home(String name, String from, int days, int hours) {
        return every(name, from, hours, days * 24 / hours);
    }

    /** {@code count} seat and motion events {@code hours} hours apart from {@code from}. */
    private static Home every(String name, String from, int hours, int count) {
        List<SensorEvent> events = new ArrayList<>();
        LocalDateTime t = LocalDateTime.parse(from);
        for (int i = 0; i < count; i++) {
            events.add(new SensorEvent(t.plusHours((long) hours * i), "Seat", "Living", Kind.PRESSURE, i % 2 == 0));
            events.add(new SensorEvent(t.plusHours((long) hours * i).plusMinutes(7), "Motion", "Living", Kind.MOTION,
                    true));
        }
        return new Home(name, events, List.of(), Path.of("m"), Path.of("h.xml"), List.of(SEAT, PIR));
    }

    /** Like Ordonez B (21 days, from a Sunday evening) hosting A (14 days, from a Monday). */
    private static final Home HOST = home("b", "2012-11-11T21:00:00", 21, 6);
    private static final Home OTHER = home("a", "2011-11-28T02:00:00", 14, 5);

    private static List<SensorEvent> second(Home two) {
        return two.events().stream().filter(e -> e.sensor().startsWith("2:")).toList();
    }

    @Test
    void theSecondResidentLivesThroughTheWholeHostRecording() {
        Home two = Variants.apply("two", HOST, OTHER);
        List<SensorEvent> second = second(two);
        LocalDateTime lastWeek = HOST.end().minusDays(7);
        assertTrue(second.stream().filter(e -> e.time().isAfter(lastWeek)).count() >= 7 * 24 / 5,
                "the second resident's events cover the host's last week too: "
                        + second.stream().filter(e -> e.time().isAfter(lastWeek)).count() + " after " + lastWeek);
        assertTrue(second.stream().filter(e -> e.time().isAfter(HOST.split())).count()
                >= second.stream().filter(e -> !e.time().isAfter(HOST.split())).count() - 2 * 24 / 5,
                "about as many second-resident events in the test half as in the history half");
        assertEquals(Set.of("2:Seat", "2:Motion"), second.stream().map(SensorEvent::sensor).collect(
                java.util.stream.Collectors.toSet()), "the same prefixed sensors in every copy");
        assertEquals(List.of("Seat", "Motion", "2:Seat", "2:Motion"), two.nodes().stream().map(NodeSpec::sensor)
                .toList(), "the second resident's nodes once, not once per copy");
        assertTrue(two.events().containsAll(HOST.events()), "the host's own events all stay");
        assertEquals(second.size(), new HashSet<>(second).size(), "copies do not overlap");
    }

    @Test
    void theSecondResidentIsNeverAwayForDays() {
        List<SensorEvent> second = second(Variants.apply("two", HOST, OTHER));
        for (int i = 1; i < second.size(); i++) {
            assertTrue(second.get(i).time().isBefore(second.get(i - 1).time().plusDays(1)),
                    "no day without the second resident: " + second.get(i - 1).time() + " -> " + second.get(i).time());
        }
        assertTrue(second.get(second.size() - 1).time().isAfter(HOST.end().minusDays(1)),
                "nor at the end: last " + second.get(second.size() - 1).time() + ", host until " + HOST.end());
    }

    /** Like Ordonez A: its last morning runs 5 h past its two weeks; the next copy takes over where it begins. */
    @Test
    void aCopyEndsWhereTheNextBegins() {
        Home overlong = every("a", "2011-11-28T02:00:00", 5, 69);
        assertTrue(overlong.end().isAfter(LocalDateTime.parse("2011-12-12T06:00:00")));
        List<SensorEvent> second = second(Variants.apply("two", HOST, overlong));
        LocalDateTime copy = LocalDateTime.parse("2012-11-19T02:00:00");
        LocalDateTime original = overlong.events().get(0).time();
        assertEquals(overlong.events().stream().filter(e -> e.time().isBefore(original.plusWeeks(1))).count(),
                second.stream().filter(e -> !e.time().isBefore(copy) && e.time().isBefore(copy.plusWeeks(1))).count(),
                "the first week of the copy from " + copy + " holds that copy's events only");
        assertTrue(second.stream().anyMatch(e -> e.time().isAfter(copy.minusHours(1)) && e.time().isBefore(copy)),
                "the copy before runs up to it");
    }

    @Test
    void copiesKeepTheOriginalsWeekdaysAndTimes() {
        Set<String> originals = new HashSet<>();
        for (SensorEvent e : OTHER.events()) {
            originals.add(e.time().getDayOfWeek() + " " + e.time().toLocalTime() + " 2:" + e.sensor() + " " + e.on());
        }
        List<SensorEvent> second = second(Variants.apply("two", HOST, OTHER));
        assertFalse(second.isEmpty());
        for (SensorEvent e : second) {
            String k = e.time().getDayOfWeek() + " " + e.time().toLocalTime() + " " + e.sensor() + " " + e.on();
            assertTrue(originals.contains(k), "a copy's event on another weekday or time than any original: " + k);
        }
    }

    @Test
    void nothingLiesOutsideTheHostsSpan() {
        for (Home[] pair : new Home[][] {{HOST, OTHER}, {OTHER, HOST}, {HOST, home("c", "2011-12-02T09:00:00", 10, 4)}}) {
            Home two = Variants.apply("two", pair[0], pair[1]);
            assertEquals(pair[0].events().get(0).time(), two.events().get(0).time(), "starts with the host");
            assertEquals(pair[0].end(), two.end(), "ends with the host");
            LocalDateTime lastWeek = pair[0].end().minusDays(7);
            assertTrue(second(two).stream().anyMatch(e -> e.time().isAfter(lastWeek)),
                    "the second resident in the host's last week with " + pair[1].name());
        }
    }

    @Test
    void noMotionDropsMotionSensorsOnly() {
        Home h = Variants.apply("nomotion", HOST, OTHER);
        assertEquals("b-no-motion", h.name());
        assertEquals(List.of(SEAT), h.nodes());
        assertEquals(HOST.events().stream().filter(e -> e.sensor().equals("Seat")).toList(), h.events());
        assertEquals(HOST.labels(), h.labels());
    }
}
