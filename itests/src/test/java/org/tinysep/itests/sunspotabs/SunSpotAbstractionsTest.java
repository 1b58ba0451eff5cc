package org.tinysep.itests.sunspotabs;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.LightBrightnessProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.MovementWithCoordinatesListener;
import org.tinysep.api.sensor.MovementWithCoordinatesProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.sensor.TemperatureProvider;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.Position;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.TemperatureStatus;
import org.tinysep.itests.Topology;

/**
 * The four Sun SPOT hardware abstractions (thesis 4.4.2.8–4.4.2.11) in a real Felix, fed with real Sun SPOT frames
 * over UDP on 127.0.0.1: a node's first frame makes the bus radio create its bus device, the abstraction of the
 * node's type creates its device, and the right typed event comes out of that device's provider service.
 *
 * <p>The first frame of a node may or may not reach a listener connected right after the device appeared (it
 * travels through the device while the test connects), so each test gives that frame a value it then ignores.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class SunSpotAbstractionsTest extends SunSpotTestSupport {

    /**
     * Sends the node's {@code first} report and waits for its abstraction: the provider of {@code type}, and the
     * device of {@code deviceType} connected to the node's bus device. @return the provider
     */
    private <P> P announce(SunSpotNode node, SunSpotPayload first, Class<P> type, String deviceType)
            throws Exception {
        node.send(first);
        P provider = awaitService(type, node.filter(), TIMEOUT);
        expectDeviceOnItsBus(deviceType, node);
        return provider;
    }

    private void expectDeviceOnItsBus(String type, SunSpotNode node) {
        String prefix = type + "@" + node.address() + " <- BusRadioSunSpotProvider of ";
        await(TIMEOUT, () -> Topology.of(context).stream().anyMatch(l -> l.startsWith(prefix)),
                type + " connected to its bus device, in " + Topology.of(context));
    }

    @Test
    public void movementNodeBecomesMovementWithCoordinates() throws Exception {
        try (SunSpotNode node = new SunSpotNode("0014.4F01.0000.0102", udpPortOf(SUN_SPOT_BUS))) {
            MovementWithCoordinatesProvider movement = announce(node, new MovementDetection(false),
                    MovementWithCoordinatesProvider.class, "SunSpotMovement");
            ServiceReference<MovementProvider> plain = context.getServiceReferences(MovementProvider.class,
                    node.filter()).iterator().next();
            assertTrue("one service under both names", context.getService(plain) == movement);
            assertEquals("SunSpotMovement", plain.getProperty(DeviceProperties.DRIVER_NAME));
            assertEquals(List.of("movement"), List.of((String[]) plain.getProperty(DeviceProperties.NODE_TYPE)));

            List<MovementEvent> reported = new CopyOnWriteArrayList<>();
            List<Coordinates> located = new CopyOnWriteArrayList<>();
            movement.connect(new MovementWithCoordinatesListener() {
                @Override
                public void movementReported(MovementProvider source, MovementEvent m) {
                    reported.add(m);
                }

                @Override
                public void movementLocated(MovementWithCoordinatesProvider source, MovementEvent m,
                        Coordinates where) {
                    located.add(where);
                }
            });
            node.send(new MovementDetection(true, new Position(120, 340, 80)));

            await(TIMEOUT, () -> !located.isEmpty(), "the motion's coordinates");
            assertEquals(List.of(new Coordinates(1.2, 3.4, 0.8)), located);
            assertEquals(1, reported.stream().filter(MovementEvent::detected).count());
            assertEquals(Optional.of(new Coordinates(1.2, 3.4, 0.8)), movement.lastCoordinates());
            assertTrue(movement.lastMovement().orElseThrow().detected());
        }
    }

    @Test
    public void temperatureNodeReportsTemperaturesBeyondTheDeadBand() throws Exception {
        try (SunSpotNode node = new SunSpotNode("0014.4F01.0000.0103", udpPortOf(SUN_SPOT_BUS))) {
            TemperatureProvider temperature = announce(node, new TemperatureStatus(18.0), TemperatureProvider.class,
                    "SunSpotTemperature");

            List<Double> heard = new CopyOnWriteArrayList<>();
            temperature.connect((src, celsius, at) -> heard.add(celsius));
            // the second 21.5 is a repeat: within the 0.1 °C dead band
            node.send(new TemperatureStatus(21.5), new TemperatureStatus(21.5), new TemperatureStatus(22.0));

            await(TIMEOUT, () -> heard.contains(22.0), "22.0 °C to reach the listener");
            assertEquals(List.of(21.5, 22.0), heard.stream().filter(c -> c != 18.0).toList());
            assertEquals(22.0, temperature.celsius().orElseThrow(), 1e-9);
        }
    }

    @Test
    public void lightNodeReportsBrightnessChanges() throws Exception {
        try (SunSpotNode node = new SunSpotNode("0014.4F01.0000.0104", udpPortOf(SUN_SPOT_BUS))) {
            LightBrightnessProvider light = announce(node, new LightStatus(10), LightBrightnessProvider.class,
                    "SunSpotLight");

            List<Percent> heard = new CopyOnWriteArrayList<>();
            light.connect((src, brightness, at) -> heard.add(brightness));
            node.send(new LightStatus(55), new LightStatus(55), new LightStatus(70)); // the repeat is not announced

            await(TIMEOUT, () -> heard.contains(Percent.of(70)), "70 % to reach the listener");
            assertEquals(List.of(Percent.of(55), Percent.of(70)),
                    heard.stream().filter(p -> p.value() != 10).toList());
            assertEquals(Optional.of(Percent.of(70)), light.brightness());
        }
    }

    @Test
    public void petCollarReportsPetMovementButNoPersonMovement() throws Exception {
        try (SunSpotNode node = new SunSpotNode("0014.4F01.0000.0105", udpPortOf(SUN_SPOT_BUS))) {
            PetMovementProvider pet = announce(node, new PetMovementDetection(false), PetMovementProvider.class,
                    "SunSpotPetMovement");

            List<MovementEvent> heard = new CopyOnWriteArrayList<>();
            pet.connect((src, m) -> heard.add(m));
            node.send(new PetMovementDetection(true));

            await(TIMEOUT, () -> heard.stream().anyMatch(MovementEvent::detected), "the pet's motion");
            assertTrue(pet.lastMovement().orElseThrow().detected());
            assertTrue("a pet is not a person: no Movement interface for the collar",
                    context.getServiceReferences(MovementProvider.class, node.filter()).isEmpty());
            assertFalse(Topology.of(context).stream().anyMatch(l -> l.startsWith("FlatOccupancy")));
        }
    }
}
