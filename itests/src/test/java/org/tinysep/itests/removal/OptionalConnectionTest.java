package org.tinysep.itests.removal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;
import static org.tinysep.amica.protocol.AmicaNodeType.SIMPLE_LIGHT;

import java.util.List;
import java.util.Set;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.Bundle;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.Topology;

/**
 * Thesis 3.3: "it is up to each device to decide whether to unregister when they lose a connection". Inactivity
 * Recognition needs an activity source (vital) and uses Flat Occupancy, Mail Manager and House Information when
 * present (optional); Follow Me Light needs a light (vital) and uses movement, Flat Occupancy and House Information
 * (optional). Losing an optional provider keeps the device, which reconnects when the provider returns; losing the
 * last vital one removes it, except for Inactivity Recognition, which watches the person and stays (issue 25).
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class OptionalConnectionTest extends RemovalTestSupport {

    private static final String MOV = "AmicaMovement@1.17";
    private static final String INACTIVITY = "InactivityRecognition";
    private static final String FOLLOW_ME = "FollowMeLight";

    @Test
    public void losingAnOptionalProviderKeepsTheDeviceWhichReconnectsWhenItReturns() throws Exception {
        try (AmicaNode movement = awakeNode(1, 17, MOVEMENT); AmicaNode light = awakeNode(1, 30, SIMPLE_LIGHT)) {
            Set<String> full = Set.of(
                    INACTIVITY + " <- MovementProvider of " + MOV,
                    INACTIVITY + " <- FlatOccupancyProvider of FlatOccupancy (optional)",
                    INACTIVITY + " <- MailManagerProvider of MailManager (optional)",
                    INACTIVITY + " <- HouseInformationProvider of HouseInformation (optional)",
                    FOLLOW_ME + " <- SimpleLightProvider of AmicaSimpleLight@1.30",
                    FOLLOW_ME + " <- MovementProvider of " + MOV + " (optional)",
                    FOLLOW_ME + " <- FlatOccupancyProvider of FlatOccupancy (optional)",
                    FOLLOW_ME + " <- HouseInformationProvider of HouseInformation (optional)");
            expectGraph(full, Set.of());
            String inactivity = Topology.uid(context, INACTIVITY, null);
            String followMe = Topology.uid(context, FOLLOW_ME, null);
            String movementUid = Topology.uid(context, "AmicaMovement", "1.17");

            for (String[] provider : List.of(new String[] {"org.tinysep.mailmanager", "MailManager"},
                    new String[] {"org.tinysep.houseinformation", "HouseInformation"},
                    new String[] {"org.tinysep.flatoccupancy", "FlatOccupancy"})) {
                Bundle b = bundle(provider[0]);
                long before = lastSequence();
                b.stop();
                Set<String> lost = full.stream().filter(l -> l.contains(" of " + provider[1] + " "))
                        .collect(java.util.stream.Collectors.toSet());
                assertTrue(provider[1] + " was a provider of both or one: " + lost, !lost.isEmpty());
                expectGraph(Set.of(INACTIVITY, FOLLOW_ME), lost);
                assertEquals("Inactivity stayed: the same device", inactivity, Topology.uid(context, INACTIVITY, null));
                assertEquals("Follow Me stayed: the same device", followMe, Topology.uid(context, FOLLOW_ME, null));
                List<EventEntry> after = entriesAfter(before, e -> true);
                assertTrue("no device of ours removed: " + after, after.stream().noneMatch(e ->
                        e.kind() == EventKind.DEVICE_REMOVED
                                && (e.origin().equals(inactivity) || e.origin().equals(followMe))));
                assertTrue("the disconnection is logged: " + after, after.stream().anyMatch(e ->
                        e.kind() == EventKind.DISCONNECTED
                                && (e.origin().equals(inactivity) || e.origin().equals(followMe))));

                b.start();
                expectGraph(full, Set.of()); // reconnected by themselves
                assertEquals(inactivity, Topology.uid(context, INACTIVITY, null));
                assertEquals(followMe, Topology.uid(context, FOLLOW_ME, null));
            }

            // contrast: the movement is Inactivity's only activity source (vital) but optional for Follow Me. Since
            // issue 25 Inactivity Recognition watches the person: it stays (a deliberate deviation from thesis 3.3)
            // and says it can no longer see what that sensor saw
            long before = lastSequence();
            Bundle amicaMovement = bundle("org.tinysep.amica.movement");
            amicaMovement.stop();
            expectGraph(Set.of(INACTIVITY, FOLLOW_ME, FOLLOW_ME + " <- SimpleLightProvider of AmicaSimpleLight@1.30"),
                    Set.of(MOV, INACTIVITY + " <- MovementProvider of " + MOV,
                            FOLLOW_ME + " <- MovementProvider of " + MOV + " (optional)"));
            assertEquals("Inactivity stayed: the same device", inactivity, Topology.uid(context, INACTIVITY, null));
            assertEquals(followMe, Topology.uid(context, FOLLOW_ME, null));
            long movementRemoved = only(before, EventKind.DEVICE_REMOVED, movementUid);
            long reduced = entriesAfter(before, e -> e.kind() == EventKind.PROBLEM && e.origin().equals(inactivity)
                    && e.message().startsWith("Monitoring reduced: ")).stream().mapToLong(EventEntry::sequence)
                    .findFirst().orElseThrow(() -> new AssertionError("no Monitoring reduced problem: "
                            + entriesAfter(before, e -> true)));
            assertBefore("the movement device goes first", movementRemoved, reduced);
            assertTrue("Inactivity is not removed", entriesAfter(before, e -> e.kind() == EventKind.DEVICE_REMOVED
                    && e.origin().equals(inactivity)).isEmpty());
            assertTrue("Follow Me is not removed", entriesAfter(before, e -> e.kind() == EventKind.DEVICE_REMOVED
                    && e.origin().equals(followMe)).isEmpty());

            amicaMovement.start(); // the bus device is still there: AmicaMovement comes back, both reconnect
            expectGraph(full, Set.of());
            assertEquals(followMe, Topology.uid(context, FOLLOW_ME, null));
        }
    }
}
