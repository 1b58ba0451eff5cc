package org.tinysep.itests.sunspotabs;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Collectors;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.MovementWithCoordinatesListener;
import org.tinysep.api.sensor.MovementWithCoordinatesProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.itests.AmicaNode;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.Position;
import org.tinysep.itests.Topology;

/**
 * Thesis 3.5 (Fig 3.6 and the interface extension): with an AmICA and a Sun SPOT movement node running, Flat
 * Occupancy — unchanged, a consumer of {@code MovementProvider} only — connects to the Sun SPOT movement device too,
 * and a Sun SPOT motion makes the flat occupied; at the same time a newer consumer connected through
 * {@code MovementWithCoordinatesProvider} gets where the motion was.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class SunSpotInterfaceExtensionTest extends SunSpotTestSupport {

    @Test
    public void flatOccupancyUsesTheSunSpotMovementWhileANewConsumerGetsCoordinates() throws Exception {
        try (AmicaNode amica = new AmicaNode(1, 17, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.MOVEMENT);
                SunSpotNode spot = new SunSpotNode("0014.4F01.0000.1234", udpPortOf(SUN_SPOT_BUS))) {
            amica.keepAlive(); // announces itself; never reports motion in this test
            spot.send(new MovementDetection(false)); // the first packet creates the Sun SPOT bus device

            Set<String> flatInputs = Set.of(
                    "FlatOccupancy <- MovementProvider of AmicaMovement@" + amica.id(),
                    "FlatOccupancy <- MovementProvider of SunSpotMovement@" + spot.address());
            await(TIMEOUT, () -> flatInputs.equals(flatConnections()), "Flat Occupancy connected to both sensors");
            assertEquals("AmICA movement is plain movement; the Sun SPOT one is also the extension", 1,
                    context.getServiceReferences(MovementWithCoordinatesProvider.class, null).size());
            assertEquals(2, context.getServiceReferences(MovementProvider.class, null).size());

            MovementWithCoordinatesProvider located = awaitService(MovementWithCoordinatesProvider.class,
                    spot.filter(), TIMEOUT);
            List<Coordinates> where = new CopyOnWriteArrayList<>();
            located.connect(new MovementWithCoordinatesListener() {
                @Override
                public void movementReported(MovementProvider source, MovementEvent movement) {
                }

                @Override
                public void movementLocated(MovementWithCoordinatesProvider source, MovementEvent movement,
                        Coordinates at) {
                    where.add(at);
                }
            });
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            List<Occupancy> heard = new CopyOnWriteArrayList<>();
            flat.connect((source, occupancy, at) -> heard.add(occupancy));
            assertEquals("no motion yet from either node", Occupancy.UNKNOWN, flat.occupancy());

            spot.send(new MovementDetection(true, new Position(250, 410, 120)));

            await(TIMEOUT, () -> heard.contains(Occupancy.OCCUPIED), "the Sun SPOT motion to reach Flat Occupancy");
            assertEquals(List.of(Occupancy.OCCUPIED), heard);
            await(TIMEOUT, () -> !where.isEmpty(), "the coordinates to reach the new consumer");
            assertEquals(List.of(new Coordinates(2.5, 4.1, 1.2)), where);
            assertEquals("Flat Occupancy still holds exactly its two movement connections", flatInputs,
                    flatConnections());
            String devices = shell("tinysep:devices");
            assertTrue(devices, devices.contains("SunSpotMovement"));
        }
    }

    private Set<String> flatConnections() {
        return Topology.of(context).stream().filter(l -> l.startsWith("FlatOccupancy <- "))
                .collect(Collectors.toSet());
    }
}
