package org.tinysep.falldetection.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.falldetection.internal.Nodes.LYING;
import static org.tinysep.falldetection.internal.Nodes.UPRIGHT;
import static org.tinysep.falldetection.internal.Nodes.burst;
import static org.tinysep.falldetection.internal.Nodes.summary;

import java.lang.reflect.Proxy;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.Reporter;
import org.tinysep.device.support.time.PlatformClock;

/** The component with a fake node and a fake alert service: a fall on the node becomes a FALL alert in words. */
class FallDetectionTest {

    private final List<AlertRequest> raised = new ArrayList<>();
    private final List<String> events = new ArrayList<>();
    private PersonNodeListener listener;
    private boolean closed;

    private final PersonNodeProvider node = new PersonNodeProvider() {
        @Override
        public String deviceUid() {
            return "5958875f-aa67-30f9-a3dc-bbb7e25beb4e";
        }

        @Override
        public Connection connect(PersonNodeListener l) {
            listener = l;
            return new Connection() {
                @Override
                public void close() {
                    closed = true;
                }

                @Override
                public boolean isOpen() {
                    return !closed;
                }
            };
        }

        @Override
        public Optional<String> person() {
            return Optional.of("Anna");
        }

        @Override
        public Optional<MovementSummary> lastSummary() {
            return Optional.empty();
        }
    };

    private FallDetection component() {
        return component(null);
    }

    private FallDetection component(LastSeen seen) {
        AlertService alerts = (AlertService) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {AlertService.class}, (p, m, a) -> {
                    if (m.getName().equals("raise")) {
                        raised.add((AlertRequest) a[0]);
                    }
                    return null;
                });
        EventLog log = (EventLog) Proxy.newProxyInstance(getClass().getClassLoader(), new Class<?>[] {EventLog.class},
                (p, m, a) -> {
                    if (m.getName().equals("record")) {
                        events.add(a[0] + " " + a[2]);
                    }
                    return null;
                });
        DriverContext ctx = new DriverContext(null, FallDetection.PID, "Fall Detection",
                new Reporter(() -> log, () -> null), new PlatformClock(Instant::now));
        return new FallDetection(ctx, FallDetectorTest.SETTINGS, ZoneOffset.UTC, alerts, seen, null);
    }

    @Test
    void aFallOnTheNodeRaisesAFallAlertThatExplainsItself() {
        FallDetection c = component();
        c.addNode(node, Map.of(DeviceProperties.NODE_ADDRESS, "0014.4F01.0000.A001"));
        for (int t = 2; t <= 10; t += 2) {
            listener.movementSummarised(node, summary(t, UPRIGHT, 250, 1500));
        }
        listener.burstReceived(node, burst(10.5, UPRIGHT, 3100, LYING));
        for (int t = 12; t <= 30; t += 2) {
            listener.movementSummarised(node, summary(t, t == 12 ? UPRIGHT : LYING, t == 12 ? 900 : 15, 1200));
        }
        assertEquals(1, raised.size(), "one alert: " + raised);
        AlertRequest r = raised.get(0);
        assertEquals(AlertKind.FALL, r.kind());
        assertEquals("Fall: Anna fell at 14:00", r.subject());
        assertTrue(r.text().contains("a hard impact (3.1 g), then lying still for 4 s"), r.text());
        assertTrue(r.text().contains("turned by 8") || r.text().contains("turned by 9"), r.text());
        assertTrue(r.text().contains("(node 0014.4F01.0000.A001)") && r.text().contains("Please check on Anna"), r.text());
        assertTrue(events.stream().anyMatch(e -> e.startsWith("DEVICE_EVENT FALL alert handed")), events.toString());
        c.removeNode(node);
        assertTrue(closed, "the node's connection is closed when it goes");
    }

    @Test
    void theAlertSaysWhereThePersonWasLastSeenOrThatNoRoomWasSeen() {
        LastSeen seen = new LastSeen(new org.tinysep.device.support.rooms.Placements() {
            @Override
            public Optional<String> roomOf(String deviceUid) {
                return Optional.of("r-bath");
            }

            @Override
            public String nameOf(String deviceUid) {
                return deviceUid;
            }
        });
        seen.rooms(List.of(new org.tinysep.api.service.Room("r-bath", "Bathroom", "Bathroom", java.util.Set.of())));
        FallDetection c = component(seen);
        c.addNode(node, Map.of(DeviceProperties.NODE_ADDRESS, "0014.4F01.0000.A001"));
        fall(0);
        assertEquals(1, raised.size(), "one alert: " + raised);
        assertTrue(raised.get(0).text().contains("(node 0014.4F01.0000.A001); no room seen yet"), raised.get(0).text());
        seen.movementReported(LastSeenTest.pir("bath-pir", org.tinysep.api.sensor.MovementLocation.INSIDE),
                new org.tinysep.api.sensor.MovementEvent(true, Nodes.T0.plusSeconds(100)));
        fall(120);
        assertEquals(2, raised.size(), "a second fall, a second alert: " + raised);
        assertTrue(raised.get(1).text().contains("(node 0014.4F01.0000.A001); last seen in the Bathroom at 14:01 by "
                + "its motion sensor. Please check on Anna."), raised.get(1).text());
    }

    /** A fall whose impact is {@code s} + 10.5 s after T0, then lying still. */
    private void fall(int s) {
        for (int t = 2; t <= 10; t += 2) {
            listener.movementSummarised(node, summary(s + t, UPRIGHT, 250, 1500));
        }
        listener.burstReceived(node, burst(s + 10.5, UPRIGHT, 3100, LYING));
        for (int t = 12; t <= 30; t += 2) {
            listener.movementSummarised(node, summary(s + t, t == 12 ? UPRIGHT : LYING, t == 12 ? 900 : 15, 1200));
        }
    }

    @Test
    void anImpossibleBurstIsRefusedAndLoggedNotAlerted() {
        FallDetection c = component();
        c.addNode(node, Map.of(DeviceProperties.NODE_ADDRESS, "0014.4F01.0000.A001"));
        List<Acceleration> s = new ArrayList<>(burst(1, UPRIGHT, 3000, LYING).samples());
        s.set(70, new Acceleration(0, 0, -32_000));
        listener.burstReceived(node, new AccelerationBurst(Nodes.T0, 50, 50, s));
        assertEquals(List.of(), raised);
        assertTrue(events.stream().anyMatch(e -> e.startsWith("PROBLEM a burst from node 0014.4F01.0000.A001 was refused")),
                events.toString());
    }
}
