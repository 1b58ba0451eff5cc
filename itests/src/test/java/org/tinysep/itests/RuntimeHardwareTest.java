package org.tinysep.itests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.DOOR;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.Bundle;
import org.osgi.framework.FrameworkUtil;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;

/**
 * docs/acceptance.md scenario 3 (thesis Fig 3.6): with the AmICA flat running and Flat Occupancy connected, the Sun SPOT
 * bundles are installed and started at runtime through the Felix shell. A Sun SPOT movement node appears and
 * Flat Occupancy connects to it, with no restart and no change to Flat Occupancy's code.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class RuntimeHardwareTest extends ThesisSliceTestSupport {

    private static final String SPOT = "0014.4F01.0000.7E11";

    /** Builds Sun SPOT frames; kept out of the test class, whose probe loads before the Sun SPOT bundles exist. */
    static final class SunSpotFrames {
        static byte[] motion(String address) {
            return org.tinysep.sunspot.protocol.SunSpotCodec.encode(new org.tinysep.sunspot.protocol.SunSpotFrame(
                    org.tinysep.sunspot.protocol.SunSpotAddress.parse(address), 2,
                    org.tinysep.sunspot.protocol.SunSpotPayloads.encode(
                            new org.tinysep.sunspot.protocol.MovementDetection(true, null))));
        }
    }

    @Test
    public void fig36SunSpotInstalledThroughTheShellJoinsTheRunningFlat() throws Exception {
        try (AmicaNode movement = awakeNode(1, 17, MOVEMENT); AmicaNode door = awakeNode(1, 20, DOOR)) {
            expectTopology(FIG_33);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            String flatUid = flat.deviceUid();
            Bundle flatBundle = FrameworkUtil.getBundle(flat.getClass());
            long flatModified = flatBundle.getLastModified();
            List<Occupancy> heard = new CopyOnWriteArrayList<>();
            flat.connect((source, occupancy, at) -> heard.add(occupancy));

            List<String> ids = new ArrayList<>();
            for (String artifact : List.of("org.tinysep.sunspot.protocol", "org.tinysep.sunspot.busradio",
                    "org.tinysep.sunspot.movement")) {
                String out = shell("install " + bundleUrl(artifact));
                Matcher m = Pattern.compile("Bundle ID: (\\d+)").matcher(out);
                assertTrue(out, m.find());
                ids.add(m.group(1));
            }
            shell("start " + String.join(" ", ids));
            for (String bsn : List.of("org.tinysep.sunspot.protocol", "org.tinysep.sunspot.busradio",
                    "org.tinysep.sunspot.movement")) {
                Bundle b = Arrays.stream(context.getBundles()).filter(x -> bsn.equals(x.getSymbolicName()))
                        .findFirst().orElseThrow(() -> new AssertionError(bsn + " not installed"));
                assertEquals(bsn + " active", Bundle.ACTIVE, b.getState());
            }

            int spotPort = udpPortOf("BusRadioSunSpot");
            byte[] frame = SunSpotFrames.motion(SPOT); // a separate class: loaded only now that the codec is installed
            try (DatagramSocket spot = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
                spot.send(new DatagramPacket(frame, frame.length, InetAddress.getLoopbackAddress(), spotPort));
                Set<String> withSpot = new TreeSet<>(FIG_33);
                withSpot.add("BusRadioSunSpot@" + SPOT);
                withSpot.add("SunSpotMovement@" + SPOT);
                withSpot.add("SunSpotMovement@" + SPOT + " <- BusRadioSunSpotProvider of BusRadioSunSpot@" + SPOT);
                withSpot.add("FlatOccupancy <- MovementProvider of SunSpotMovement@" + SPOT);
                expectTopology(withSpot);
            }

            assertEquals("the same Flat Occupancy device: no restart", flatUid,
                    awaitService(FlatOccupancyProvider.class, null, TIMEOUT).deviceUid());
            assertEquals("Flat Occupancy's bundle untouched", Bundle.ACTIVE, flatBundle.getState());
            assertEquals("Flat Occupancy's bundle not updated", flatModified, flatBundle.getLastModified());
            await(TIMEOUT, () -> heard.contains(Occupancy.OCCUPIED), "the Sun SPOT movement to occupy the flat");
        }
    }
}
