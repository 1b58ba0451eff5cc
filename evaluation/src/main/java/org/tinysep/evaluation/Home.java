package org.tinysep.evaluation;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.tinysep.simulator.replay.ConvertOrdonez;
import org.tinysep.simulator.replay.EventsCsv;
import org.tinysep.simulator.replay.Label;
import org.tinysep.simulator.replay.LabelsCsv;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.ReplayFormatException;
import org.tinysep.simulator.replay.ReplayPlan;
import org.tinysep.simulator.replay.SensorEvent;
import org.tinysep.simulator.replay.SensorMapping;

/**
 * A recorded home ready for evaluation: its events and labels (simulator/README-replay.md formats), the mapping pinned to the node
 * addresses of the whole recording (so a window replayed later finds the same devices in a snapshot), the House
 * Information file and placements, and the split into history (first half) and test (second half).
 *
 * @param name    e.g. {@code ordonez-a}
 * @param events  every recorded event, in time order
 * @param labels  every label
 * @param mapping the pinned mapping file
 * @param house   the House Information file
 * @param nodes   the plan's nodes
 * @param residents how many people live there (Inactivity Recognition's {@code residents}, as an installer sets it),
 *                0 when nobody says: the detector recognises them from the history (the default, as on an unseen
 *                home); a folder declares them in an optional file {@code residents} (one number), {@code
 *                ./evaluate.sh --residents N} for any home
 */
record Home(String name, List<SensorEvent> events, List<Label> labels, Path mapping, Path house, List<NodeSpec> nodes,
        int residents) {

    /** A home whose residents nobody declares (recognised from the history). */
    Home(String name, List<SensorEvent> events, List<Label> labels, Path mapping, Path house, List<NodeSpec> nodes) {
        this(name, events, labels, mapping, house, nodes, 0);
    }

    /** @return this home with {@code n} residents declared (0: recognised from the history) */
    Home withResidents(int n) {
        return new Home(name, events, labels, mapping, house, nodes, n);
    }

    /**
     * @param spec    {@code A}/{@code B} (Ordonez, converted from {@code ordonezDir} by the simulator's converter) or a
     *                folder with {@code events.csv}, {@code labels.csv} and optionally {@code mapping} and
     *                {@code house.xml} and {@code residents}
     * @param work    a folder for the converted files
     */
    static Home load(String spec, Path ordonezDir, Path work) throws IOException, ReplayFormatException {
        return load(spec, ordonezDir, work, LabelWords.defaults());
    }

    /** As {@link #load(String, Path, Path)}, with {@code words} deciding which labels mean away and asleep. */
    static Home load(String spec, Path ordonezDir, Path work, LabelWords words)
            throws IOException, ReplayFormatException {
        Files.createDirectories(work);
        Path dir;
        String name;
        SensorMapping mapping;
        Path house;
        if (spec.matches("(?i)[ab]")) {
            String letter = spec.toUpperCase();
            name = "ordonez-" + letter.toLowerCase();
            dir = work.resolve(name);
            System.out.println("converting Ordonez " + letter + ": " + ConvertOrdonez.convert(ordonezDir, letter, dir));
            mapping = SensorMapping.fromResource(name + ".mapping");
            house = resource("replay/" + name + ".house.xml", work.resolve(name + ".house.xml"));
        } else {
            dir = Path.of(spec);
            name = dir.toAbsolutePath().normalize().getFileName().toString();
            Path m = dir.resolve("mapping");
            mapping = Files.isRegularFile(m) ? SensorMapping.read(m) : SensorMapping.defaults();
            house = dir.resolve("house.xml");
        }
        List<SensorEvent> events = EventsCsv.read(dir.resolve("events.csv"));
        Path labelFile = dir.resolve("labels.csv");
        if (!Files.isRegularFile(labelFile)) {
            throw new IOException(labelFile + " is missing: collapses are drawn from the labels' at-home, awake time");
        }
        List<Label> recorded = LabelsCsv.read(labelFile);
        System.out.println(words.describe(recorded));
        List<Label> labels = words.normalise(recorded);
        ReplayPlan plan = ReplayPlan.of(events, mapping);
        if (!Files.isRegularFile(house)) {
            house = HouseFile.write(rooms(plan), work.resolve(name + ".house.xml"));
        }
        Path pinned = work.resolve(name + ".pinned.mapping");
        Files.write(pinned, pinned(plan));
        return new Home(name, events, labels, pinned, house, plan.nodes(), residents(dir.resolve("residents")));
    }

    /**
     * @param file optional: the number of people living in the home (one line; {@code #} comments and blank lines
     *             skipped), as the installer would set Inactivity Recognition's {@code residents}
     * @return that number, or 0 (none declared: recognised from the history) without the file
     */
    static int residents(Path file) throws IOException {
        if (!Files.isRegularFile(file)) {
            return 0;
        }
        List<String> lines = Files.readAllLines(file).stream().map(String::strip)
                .filter(l -> !l.isEmpty() && !l.startsWith("#")).toList();
        if (lines.size() != 1 || !lines.get(0).matches("\\d{1,3}")) {
            throw new IOException(file + " must hold one whole number, the people living in the home (0: recognise "
                    + "them from the history), not " + lines);
        }
        return Integer.parseInt(lines.get(0));
    }

    /** @return the instant splitting history (before) from test (from it on): the recording's middle */
    LocalDateTime split() {
        LocalDateTime a = events.get(0).time();
        LocalDateTime b = events.get(events.size() - 1).time();
        return a.plusSeconds(Duration.between(a, b).toSeconds() / 2);
    }

    LocalDateTime end() {
        return events.get(events.size() - 1).time();
    }

    /** @return the placement configuration value {@code NG.ADDR=Room, ...} */
    String placements() {
        List<String> p = new ArrayList<>();
        nodes.forEach(n -> p.add(n.address() + "=" + n.room()));
        return String.join(", ", p);
    }

    /** Every sensor with its node, type, room and name spelled out: allocation no longer depends on the events. */
    private static List<String> pinned(ReplayPlan plan) {
        List<String> lines = new ArrayList<>(List.of("# pinned by the evaluation harness from the whole recording"));
        for (NodeSpec n : plan.nodes()) {
            lines.add("sensor = " + n.sensor() + "; node = amica " + n.address() + "; type = " + n.type().typeName()
                    + (n.doorKind().isEmpty() ? "" : "; doorKind = " + n.doorKind()) + "; room = " + n.room()
                    + "; name = " + n.name());
        }
        return lines;
    }

    private static Set<String> rooms(ReplayPlan plan) {
        Set<String> rooms = new LinkedHashSet<>();
        plan.nodes().forEach(n -> rooms.add(n.room()));
        return rooms;
    }

    private static Path resource(String name, Path to) throws IOException {
        try (InputStream in = ReplayPlan.class.getClassLoader().getResourceAsStream(name)) {
            if (in == null) {
                throw new IOException("no resource " + name + " in the simulator jar");
            }
            Files.copy(in, to, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        return to;
    }
}
