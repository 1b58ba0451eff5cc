package org.tinysep.sunspot.movement.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.MovementWithCoordinatesListener;
import org.tinysep.api.sensor.MovementWithCoordinatesProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.Position;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** Movement Detection payloads in, movement reports (and coordinates) out. */
class SunSpotMovementDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private static final int MOVEMENT = SunSpotSensorType.MOVEMENT.code();

    private final FakeSunSpotBus bus = new FakeSunSpotBus();
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final SunSpotMovementDevice movement = new SunSpotMovementDevice(
            new DriverContext(null, "d", "SunSpotMovement", logs.reporter(), new PlatformClock(() -> T0)), bus);

    private void feed(int sensorType, byte[] payload, Instant at) {
        movement.payloadReceived(bus, sensorType, payload, at);
    }

    @Test
    void everyReportIsPassedOnAndOtherSensorsOfTheNodeAreIgnored() {
        List<MovementEvent> seen = new ArrayList<>();
        movement.connect((src, e) -> seen.add(e));

        feed(MOVEMENT, SunSpotPayloads.encode(new MovementDetection(true, null)), T0);
        feed(SunSpotSensorType.TEMPERATURE.code(), SunSpotPayloads.encode(new TemperatureStatus(21.5)),
                T0.plusSeconds(1));
        feed(SunSpotSensorType.LIGHT.code(), SunSpotPayloads.encode(new LightStatus(40)), T0.plusSeconds(1));
        feed(MOVEMENT, SunSpotPayloads.encode(new MovementDetection(true, null)), T0.plusSeconds(2));
        feed(MOVEMENT, SunSpotPayloads.encode(new MovementDetection(false, null)), T0.plusSeconds(4));

        assertEquals(List.of(new MovementEvent(true, T0), new MovementEvent(true, T0.plusSeconds(2)),
                new MovementEvent(false, T0.plusSeconds(4))), seen);
        assertEquals(new MovementEvent(false, T0.plusSeconds(4)), movement.lastMovement().orElseThrow());
        long logged = logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT).count();
        assertEquals(2, logged, "the event log gets changes only: motion, then no motion");
        assertEquals(DeviceStatus.State.ONLINE, movement.status().state());
        assertEquals("0", parameter("rejectedPayloads"), "other sensors' frames are not rejects");
    }

    @Test
    void coordinatesReachOnlyListenersThatAskForThemInMetres() {
        List<String> plain = new ArrayList<>();
        List<String> located = new ArrayList<>();
        movement.connect((src, e) -> plain.add("moved " + e.detected()));
        movement.connect(new MovementWithCoordinatesListener() {
            @Override
            public void movementReported(MovementProvider source, MovementEvent m) {
                located.add("moved " + m.detected());
            }

            @Override
            public void movementLocated(MovementWithCoordinatesProvider source, MovementEvent m, Coordinates where) {
                assertEquals(movement, source);
                located.add("at " + where);
            }
        });
        assertEquals(Optional.empty(), movement.lastCoordinates());

        feed(MOVEMENT, SunSpotPayloads.encode(new MovementDetection(true, new Position(120, -340, 85))), T0);
        feed(MOVEMENT, SunSpotPayloads.encode(new MovementDetection(true, null)), T0.plusSeconds(2));

        Coordinates expected = new Coordinates(1.2, -3.4, 0.85);
        assertEquals(List.of("moved true", "moved true"), plain);
        assertEquals(List.of("moved true", "at " + expected, "moved true"), located);
        assertEquals(Optional.empty(), movement.lastCoordinates(), "the latest motion came without a position");

        feed(MOVEMENT, SunSpotPayloads.encode(new MovementDetection(true, new Position(0, 250, 0))),
                T0.plusSeconds(4));
        assertEquals(Optional.of(new Coordinates(0, 2.5, 0)), movement.lastCoordinates());
    }

    @Test
    void badPayloadsGiveNoEventAndNoExceptionButAnErrorStatus() {
        List<MovementEvent> seen = new ArrayList<>();
        movement.connect((src, e) -> seen.add(e));

        feed(MOVEMENT, new byte[] {2, 1}, T0); // truncated
        feed(MOVEMENT, new byte[] {9, 9, 9, 9}, T0); // unknown payload
        feed(MOVEMENT, new byte[0], T0);
        feed(MOVEMENT, SunSpotPayloads.encode(new TemperatureStatus(20.0)), T0); // header says movement

        assertEquals(List.of(), seen);
        assertEquals(DeviceStatus.State.ERROR, movement.status().state());
        assertEquals("4", parameter("rejectedPayloads"));
        assertTrue(movement.lastMovement().isEmpty());

        feed(MOVEMENT, SunSpotPayloads.encode(new MovementDetection(true, null)), T0.plusSeconds(1));
        assertEquals(List.of(new MovementEvent(true, T0.plusSeconds(1))), seen);
        assertEquals(DeviceStatus.State.ONLINE, movement.status().state(), "a good payload clears the error");
    }

    @Test
    void locationChangeIsValidatedAndAnnounced() {
        List<MovementLocation> seen = new ArrayList<>();
        movement.connect(new org.tinysep.api.sensor.MovementListener() {
            @Override
            public void movementReported(MovementProvider source, MovementEvent m) {
            }

            @Override
            public void locationChanged(MovementProvider source, MovementLocation l, Instant at) {
                seen.add(l);
            }
        });
        assertEquals(MovementLocation.INSIDE, movement.location());
        movement.setParameter("location", " outside ");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> movement.setParameter("location", "garden"));
        assertEquals("location must be INSIDE or OUTSIDE, was 'garden'", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> movement.setParameter("lastCoordinates", "1,2,3"));
        assertEquals(List.of(MovementLocation.OUTSIDE), seen);
        assertEquals(MovementLocation.OUTSIDE, movement.location());
    }

    @Test
    void identityFollowsTheBusDevice() {
        assertEquals("Movement sensor 0014.4F01.0000.1234", movement.name());
        assertEquals(org.tinysep.device.support.lifecycle.Uids.of("SunSpotMovement", "bus-1"), movement.uid());
    }

    private String parameter(String key) {
        return movement.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}
