package org.tinysep.itests.aal;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;
import static org.tinysep.amica.protocol.AmicaNodeType.PET_COLLAR;

import java.util.List;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;

/**
 * Issue 25, item 1, end to end in a real Felix: a movement node placed in the bathroom, then ONE keep-alive for the
 * same node address claiming the pet-collar type, sent over UDP from another socket on 127.0.0.1 (anyone on the
 * machine can). The node keeps its type, its movement device (same UID) and the watching services stay, the mismatch
 * is counted and reported as a "Node type mismatch: " PROBLEM; only the installer's confirmation re-types the node.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class SpoofedKeepAliveTest extends AalTestSupport {

    private Device busDevice(String node) {
        return awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=" + BUS + ")("
                + DeviceProperties.NODE_ADDRESS + "=" + node + "))", TIMEOUT);
    }

    private Object nodeTypeProperty(String busUid) throws Exception {
        ServiceReference<?>[] refs = context.getServiceReferences(Device.class.getName(),
                "(" + DeviceProperties.DEVICE_UID + "=" + busUid + ")");
        assertNotNull("the bus device " + busUid, refs);
        return refs[0].getProperty(DeviceProperties.NODE_TYPE);
    }

    private boolean registered(String deviceUid) {
        try {
            return context.getServiceReferences(Device.class.getName(),
                    "(" + DeviceProperties.DEVICE_UID + "=" + deviceUid + ")") != null;
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    private List<String> mismatchProblems() {
        return awaitService(EventLog.class, null, TIMEOUT).recent(100_000).stream()
                .filter(e -> e.kind() == EventKind.PROBLEM).map(EventEntry::message)
                .filter(m -> m.startsWith("Node type mismatch: ")).toList();
    }

    @Test
    public void aForgedPetCollarKeepAliveChangesNothingUntilTheInstallerConfirms() throws Exception {
        try (SyncPeer sync = sync(); AmicaNode bath = node(1, 40, MOVEMENT);
                AmicaNode forger = node(1, 40, PET_COLLAR)) {
            sync.tickDone(tomorrow());
            Device movement = placeIn(bath, "AmicaMovement", "Bathroom");
            String inactivityUid = awaitService(InactivityRecognitionProvider.class, null, TIMEOUT).deviceUid();
            String flatUid = awaitService(FlatOccupancyProvider.class, null, TIMEOUT).deviceUid();
            Device bus = busDevice("1.40");
            long packets = Long.parseLong(parameter(bus, "packets"));

            forger.keepAlive(); // one datagram, from another port of 127.0.0.1
            await(TIMEOUT, () -> Long.parseLong(parameter(bus, "packets")) == packets + 1, "the forged frame handled");

            assertTrue("the movement device is still there, same UID", registered(movement.uid()));
            assertArrayEquals("node type unchanged", new String[] {"movement"},
                    (String[]) nodeTypeProperty(bus.uid()));
            assertTrue("Inactivity Recognition still watching", registered(inactivityUid));
            assertTrue("Flat Occupancy still watching", registered(flatUid));
            assertEquals("1", parameter(bus, "typeMismatches"));
            assertTrue(parameter(bus, "pendingNodeTypes"), parameter(bus, "pendingNodeTypes").startsWith(
                    "pet-collar (from 127.0.0.1:"));
            await(TIMEOUT, () -> !mismatchProblems().isEmpty(), "the PROBLEM in the event log (written on its thread)");
            List<String> problems = mismatchProblems();
            assertEquals(problems.toString(), 1, problems.size());
            assertTrue(problems.get(0), problems.get(0).startsWith("Node type mismatch: AmICA node 1.40 is a movement"
                    + " node (used by '" + movement.name() + "' in Bathroom), but a keep-alive from 127.0.0.1:"));
            assertTrue(problems.get(0), problems.get(0).contains("claims it is a pet-collar node. Nothing was"
                    + " changed"));
            assertTrue(problems.get(0), problems.get(0).endsWith("the installer confirms with: tinysep:invoke "
                    + bus.uid() + " acceptNodeTypes."));
            String driver = shell("tinysep:drivers");
            assertTrue(driver, driver.contains("typeMismatches=1"));

            // a real change, confirmed by the installer: the node becomes a pet collar, its devices follow
            forger.keepAlive(); // the node keeps claiming it (the last claim is what is applied)
            await(TIMEOUT, () -> parameter(bus, "typeMismatches").equals("2"), "the second claim counted");
            assertEquals("the same claim is reported once", 1, mismatchProblems().size());
            String out = shell("tinysep:invoke " + bus.uid() + " acceptNodeTypes");
            assertTrue(out, out.contains("node types now [pet-collar] (were [movement])"));
            assertArrayEquals(new String[] {"pet-collar"}, (String[]) nodeTypeProperty(bus.uid()));
            awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=AmicaPetMovement)("
                    + DeviceProperties.NODE_ADDRESS + "=1.40))", TIMEOUT);
            await(TIMEOUT, () -> !registered(movement.uid()), "the movement device gone with the movement type");
            assertTrue(awaitService(EventLog.class, null, TIMEOUT).recent(100_000).stream().anyMatch(e -> e.message()
                    .startsWith("node types changed from [movement] to [pet-collar]: confirmed by the installer")));
        }
    }
}
