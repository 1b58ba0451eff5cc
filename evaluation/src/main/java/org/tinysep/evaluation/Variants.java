package org.tinysep.evaluation;

import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * Homes derived from a recorded one, to check the detector beyond the recorded sensor mix ({@link CoreSweep} only;
 * nothing here is published as a platform figure):
 * <ul>
 * <li>{@code nomotion}: every motion sensor removed (a home with reed switches, mats and a flush only);</li>
 * <li>{@code two}: a second resident — the other Ordonez home's events laid over this one's days (whole weeks
 * apart, so weekdays match), its sensors in the rooms of the same names. Collapses are drawn from this home's
 * labels, so the second resident keeps living while the first has collapsed.</li>
 * </ul>
 */
final class Variants {

    private Variants() {
    }

    static Home apply(String variant, Home h, Home other) {
        return switch (variant) {
        case "nomotion" -> {
            List<String> motion = h.nodes().stream().filter(NodeSpec::isMotion).map(NodeSpec::sensor).toList();
            yield new Home(h.name() + "-no-motion", h.events().stream().filter(e -> !motion.contains(e.sensor()))
                    .toList(), h.labels(), h.mapping(), h.house(), h.nodes().stream().filter(n -> !n.isMotion())
                    .toList());
        }
        case "two" -> {
            long weeks = ChronoUnit.WEEKS.between(other.events().get(0).time().toLocalDate(),
                    h.events().get(0).time().toLocalDate());
            List<SensorEvent> all = new ArrayList<>(h.events());
            List<NodeSpec> nodes = new ArrayList<>(h.nodes());
            for (NodeSpec n : other.nodes()) {
                nodes.add(new NodeSpec("2:" + n.sensor(), n.family(), n.address(), n.type(), n.room(), n.doorKind(),
                        "second resident's " + n.name()));
            }
            for (SensorEvent e : other.events()) {
                SensorEvent s = new SensorEvent(e.time().plusWeeks(weeks), "2:" + e.sensor(), e.room(), e.kind(),
                        e.on());
                if (!s.time().isBefore(h.events().get(0).time()) && !s.time().isAfter(h.end())) {
                    all.add(s);
                }
            }
            all.sort(Comparator.comparing(SensorEvent::time));
            yield new Home(h.name() + "-two-residents", all, h.labels(), h.mapping(), h.house(), nodes);
        }
        default -> h;
        };
    }
}
