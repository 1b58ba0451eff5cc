package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The real Ordonez files (Ordonez, de Toledo, Sanchis, Sensors 2013, 13, 5460-5477): counts, mapping, round trip. */
class OrdonezRealDataTest {

    @TempDir
    Path tmp;

    @Test
    void homeAHas409IntervalsAnd248Labels() throws Exception {
        List<SensorEvent> events = OrdonezReader.readSensors(OrdonezData.file("OrdonezA_Sensors.txt"));
        assertEquals(818, events.size());
        assertEquals(409, events.stream().filter(SensorEvent::on).count());
        assertTimeOrdered(events);
        assertEquals(Map.ofEntries(Map.entry("Basin", 70), Map.entry("Bed", 15), Map.entry("Cabinet", 16),
                Map.entry("Cooktop", 13), Map.entry("Cupboard", 34), Map.entry("Fridge", 56),
                Map.entry("Maindoor", 31), Map.entry("Microwave", 20), Map.entry("Seat", 81),
                Map.entry("Shower", 14), Map.entry("Toaster", 14), Map.entry("Toilet", 45)),
                new TreeMap<>(Evaluation.onCountsPerSensor(events)));
        List<Label> labels = OrdonezReader.readLabels(OrdonezData.file("OrdonezA_ADLs.txt"));
        assertEquals(248, labels.size());
        assertEquals(14, labels.stream().filter(l -> l.activity().equals("Leaving")).count());
        assertEquals(3, labels.stream().filter(l -> !l.isProper()).count(), "three labels of A end before they start");
        assertEquals("2011-11-28T02:27:59", events.get(0).time().toString());
    }

    @Test
    void homeBHas2334IntervalsAnd493Labels() throws Exception {
        List<SensorEvent> events = OrdonezReader.readSensors(OrdonezData.file("OrdonezB_Sensors.txt"));
        assertEquals(4668, events.size());
        assertTimeOrdered(events);
        assertEquals(Map.ofEntries(Map.entry("Basin", 125), Map.entry("Bed", 30), Map.entry("Cupboard", 20),
                Map.entry("Door Bedroom", 362), Map.entry("Door Kitchen", 558), Map.entry("Door Living", 814),
                Map.entry("Fridge", 107), Map.entry("Maindoor", 78), Map.entry("Microwave", 22),
                Map.entry("Seat", 113), Map.entry("Shower", 12), Map.entry("Toilet", 93)),
                new TreeMap<>(Evaluation.onCountsPerSensor(events)));
        List<Label> labels = OrdonezReader.readLabels(OrdonezData.file("OrdonezB_ADLs.txt"));
        assertEquals(493, labels.size());
        assertEquals(38, labels.stream().filter(l -> l.activity().equals("Leaving")).count());
    }

    @Test
    void everySensorIsCoveredByItsMappingFile() throws Exception {
        checkCoverage("OrdonezA_Sensors.txt", "ordonez-a");
        checkCoverage("OrdonezB_Sensors.txt", "ordonez-b");
    }

    @Test
    void roundTripThroughEventsCsvAndLabelsCsv() throws Exception {
        for (String home : List.of("A", "B")) {
            List<SensorEvent> events = OrdonezReader.readSensors(OrdonezData.file("Ordonez" + home + "_Sensors.txt"));
            Path csv = tmp.resolve("events-" + home + ".csv");
            EventsCsv.write(events, csv);
            assertEquals(events, EventsCsv.read(csv));
            List<Label> labels = OrdonezReader.readLabels(OrdonezData.file("Ordonez" + home + "_ADLs.txt"));
            Path lcsv = tmp.resolve("labels-" + home + ".csv");
            LabelsCsv.write(labels, lcsv);
            assertEquals(labels, LabelsCsv.read(lcsv));
        }
    }

    @Test
    void converterWritesBothFilesForHomeA() throws Exception {
        Path out = tmp.resolve("a");
        assertEquals("818 events, 248 labels", ConvertOrdonez.convert(OrdonezData.DIR, "A", out));
        assertEquals(OrdonezReader.readSensors(OrdonezData.file("OrdonezA_Sensors.txt")),
                EventsCsv.read(out.resolve("events.csv")));
        assertEquals(249, java.nio.file.Files.readAllLines(out.resolve("labels.csv")).size());
    }

    private static void checkCoverage(String data, String home) throws Exception {
        String mappingResource = home + ".mapping";
        List<SensorEvent> events = OrdonezReader.readSensors(OrdonezData.file(data));
        SensorMapping mapping = SensorMapping.fromResource(mappingResource);
        Set<String> houseRooms = roomNames("/replay/" + home + ".house.xml");
        Set<String> sensors = Evaluation.onCountsPerSensor(events).keySet();
        for (String s : sensors) {
            assertTrue(mapping.isMapped(s), s + " of " + data + " is not in " + mappingResource);
        }
        assertEquals(sensors, new HashSet<>(mapping.mappedSensors()), "mapping names sensors the data lacks");
        ReplayPlan plan = ReplayPlan.of(events, mapping);
        assertEquals(sensors.size(), plan.nodes().size());
        assertEquals(events.size(), plan.actions().size());
        Set<String> addresses = new HashSet<>();
        for (NodeSpec n : plan.nodes()) {
            assertTrue(addresses.add(n.address().toString()), "duplicate address " + n.address());
            assertTrue(n.address().address() < mapping.firstFree().address(), n + " was allocated, not mapped");
            assertTrue(houseRooms.contains(n.room()), n + ": room not in " + home + ".house.xml " + houseRooms);
        }
        assertEquals(1, plan.nodes().stream().filter(n -> "OUTER".equals(n.doorKind())).count(), "one outer door");
    }

    private static Set<String> roomNames(String resource) throws Exception {
        javax.xml.parsers.DocumentBuilderFactory f = javax.xml.parsers.DocumentBuilderFactory.newInstance();
        f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        try (java.io.InputStream in = OrdonezRealDataTest.class.getResourceAsStream(resource)) {
            org.w3c.dom.NodeList names = f.newDocumentBuilder().parse(in).getElementsByTagName("NAME");
            Set<String> out = new HashSet<>();
            for (int i = 0; i < names.getLength(); i++) {
                out.add(names.item(i).getTextContent().strip());
            }
            assertEquals(5, out.size(), resource);
            return out;
        }
    }

    private static void assertTimeOrdered(List<SensorEvent> events) {
        for (int i = 1; i < events.size(); i++) {
            assertFalse(events.get(i).time().isBefore(events.get(i - 1).time()), "out of order at " + i);
        }
    }
}
