package org.tinysep.evaluation;

import java.time.Duration;
import java.time.LocalDateTime;
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
 * <li>{@code two}: a second resident — the other Ordonez home's events laid over this one's days, its sensors
 * ({@code "2:"}-prefixed, the same ones in every copy) in the rooms of the same names. The other recording is laid
 * over again and again so the second resident lives through the WHOLE host recording (history and test half alike):
 * each copy is shifted by a further whole multiple of the other recording's length rounded up to whole weeks (Ordonez
 * A's 14 days: every 2 weeks; B's 21 days: every 3 weeks), so weekdays still match; a copy ends where the next begins,
 * and events of a copy outside the host recording's span are dropped. (Until session 35 it was laid over once, so
 * on B the second resident lived only in B's first 14 days: a resident who moved out before the test half.)
 * Collapses are drawn from this home's labels, so the second resident keeps living while the first has
 * collapsed. Like an unseen home it declares no residents unless both recordings declare theirs (then their sum,
 * Inactivity Recognition's {@code residents}): the detector recognises them from the history (session 36b); it
 * never reads the {@code "2:"} prefix.</li>
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
                    .toList(), h.residents());
        }
        case "two" -> {
            List<SensorEvent> all = new ArrayList<>(h.events());
            all.addAll(secondResident(h, other));
            List<NodeSpec> nodes = new ArrayList<>(h.nodes());
            for (NodeSpec n : other.nodes()) {
                nodes.add(new NodeSpec("2:" + n.sensor(), n.family(), n.address(), n.type(), n.room(), n.doorKind(),
                        "second resident's " + n.name()));
            }
            all.sort(Comparator.comparing(SensorEvent::time));
            // declared only when both homes declare theirs; else, as on an unseen home, recognised from the history
            yield new Home(h.name() + "-two-residents", all, h.labels(), h.mapping(), h.house(), nodes,
                    h.residents() > 0 && other.residents() > 0 ? h.residents() + other.residents() : 0);
        }
        default -> h;
        };
    }

    /**
     * The other home's events, {@code "2:"}-prefixed, laid over the host's span again and again: copies shifted by
     * whole weeks, one after the other a whole multiple of the other recording's length apart (its length in whole
     * days, first to last event rounded to the nearest day: Ordonez A 14, B 21; rounded up to whole weeks), from the
     * copy covering the host's first event to the one covering its last. A copy ends where the next one begins (A's
     * last morning, 5 h past its two weeks, would otherwise overlap the next copy's first night); events outside the
     * host's span are dropped.
     */
    static List<SensorEvent> secondResident(Home h, Home other) {
        LocalDateTime first = other.events().get(0).time();
        long days = Math.max(1, Math.round(Duration.between(first, other.end()).toMinutes() / 1440.0));
        long period = (days + 6) / 7;
        LocalDateTime start = h.events().get(0).time();
        long weeks = ChronoUnit.WEEKS.between(first.toLocalDate(), start.toLocalDate());
        while (first.plusWeeks(weeks).isAfter(start)) {
            weeks -= period;
        }
        List<SensorEvent> out = new ArrayList<>();
        for (; !first.plusWeeks(weeks).isAfter(h.end()); weeks += period) {
            LocalDateTime next = first.plusWeeks(weeks + period);
            for (SensorEvent e : other.events()) {
                LocalDateTime t = e.time().plusWeeks(weeks);
                if (!t.isBefore(start) && !t.isAfter(h.end()) && t.isBefore(next)) {
                    out.add(new SensorEvent(t, "2:" + e.sensor(), e.room(), e.kind(), e.on()));
                }
            }
        }
        return out;
    }
}
