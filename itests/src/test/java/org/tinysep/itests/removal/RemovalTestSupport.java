package org.tinysep.itests.removal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Predicate;
import org.osgi.framework.Bundle;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.itests.TinySepTestSupport;
import org.tinysep.itests.Topology;

/**
 * Shared by the removal tests (thesis 3.3, issue 6 point 2): the Fig 3.3 drivers plus a simple light, House
 * Information, Mail Manager, Inactivity Recognition and Follow Me Light, whose connections are partly vital and
 * partly optional. Helpers read the device graph ({@link Topology}) and the event log.
 */
abstract class RemovalTestSupport extends TinySepTestSupport {

    @Override
    protected List<String> applications() {
        List<String> apps = new ArrayList<>(FIRST_SLICE);
        apps.addAll(List.of("org.tinysep.amica.simplelight", "org.tinysep.houseinformation",
                "org.tinysep.mailmanager", "org.tinysep.inactivity", "org.tinysep.followmelight"));
        return apps;
    }

    Bundle bundle(String symbolicName) {
        return Arrays.stream(context.getBundles()).filter(b -> symbolicName.equals(b.getSymbolicName())).findFirst()
                .orElseThrow(() -> new AssertionError(symbolicName + " not installed"));
    }

    /** Waits until the graph holds every line of {@code present} and none of {@code absent}. */
    void expectGraph(Set<String> present, Set<String> absent) {
        try {
            await(TIMEOUT, () -> {
                Set<String> now = Topology.of(context);
                return now.containsAll(present) && absent.stream().noneMatch(now::contains);
            }, "graph with " + present + " and without " + absent);
        } catch (AssertionError timeout) {
            Set<String> now = new TreeSet<>(Topology.of(context));
            Set<String> missing = new TreeSet<>(present);
            missing.removeAll(now);
            Set<String> extra = new TreeSet<>(absent);
            extra.retainAll(now);
            throw new AssertionError("missing " + missing + ", unexpected " + extra + " in " + now, timeout);
        }
    }

    /** @return the lines of the graph that start with {@code label} */
    Set<String> linesOf(String label) {
        Set<String> out = new TreeSet<>();
        for (String l : Topology.of(context)) {
            if (l.equals(label) || l.startsWith(label + " <- ")) {
                out.add(l);
            }
        }
        return out;
    }

    EventLog eventLog() {
        return awaitService(EventLog.class, null, TIMEOUT);
    }

    long lastSequence() {
        List<EventEntry> last = eventLog().recent(1);
        return last.isEmpty() ? 0 : last.get(0).sequence();
    }

    /** @return the event-log entries after {@code sequence} that match, oldest first */
    List<EventEntry> entriesAfter(long sequence, Predicate<EventEntry> filter) {
        return eventLog().recent(100_000).stream().filter(e -> e.sequence() > sequence).filter(filter).toList();
    }

    /** @return the sequence of the only entry after {@code sequence} of that kind and origin */
    long only(long sequence, EventKind kind, String origin) {
        List<EventEntry> found = entriesAfter(sequence, e -> e.kind() == kind && e.origin().equals(origin));
        assertEquals(kind + " of " + origin + " exactly once: " + found, 1, found.size());
        return found.get(0).sequence();
    }

    static void assertBefore(String what, long first, long second) {
        assertTrue(what + " (" + first + " before " + second + ")", first < second);
    }
}
