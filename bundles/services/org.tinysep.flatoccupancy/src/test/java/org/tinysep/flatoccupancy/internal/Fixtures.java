package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Optional;
import org.tinysep.api.device.Connection;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowListener;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.api.sensor.presence.PresenceListener;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * What these tests build: the device (T = 10 min, G = 10 s) and the sensors they hand to it directly, of which
 * only identity and kind matter (connecting needs a framework, so they refuse it; the tests call the device's
 * listener methods themselves).
 */
final class Fixtures {

    private Fixtures() {
    }

    /** @return a Flat Occupancy device whose platform clock stands at {@code now}, logging into {@code logs} */
    static FlatOccupancyDevice flat(RecordingLogs logs, Instant now) {
        return new FlatOccupancyDevice(new DriverContext(null, "d", "FlatOccupancy", logs.reporter(),
                new PlatformClock(() -> now)), Duration.ofMinutes(10), Duration.ofSeconds(10));
    }

    private static Connection refused() {
        throw new UnsupportedOperationException("the tests call the listener methods themselves");
    }

    /** @return an outer door */
    static DoorProvider door(String uid) {
        return door(uid, DoorKind.OUTER);
    }

    static DoorProvider door(String uid, DoorKind kind) {
        return new DoorProvider() {
            @Override
            public String deviceUid() {
                return uid;
            }

            @Override
            public Connection connect(DoorListener listener) {
                return refused();
            }

            @Override
            public OpenState state() {
                return OpenState.UNKNOWN;
            }

            @Override
            public DoorKind kind() {
                return kind;
            }
        };
    }

    /** @return the hall's movement sensor, inside */
    static MovementProvider movement() {
        return new MovementProvider() {
            @Override
            public String deviceUid() {
                return "hall-movement";
            }

            @Override
            public Connection connect(MovementListener listener) {
                return refused();
            }

            @Override
            public Optional<MovementEvent> lastMovement() {
                return Optional.empty();
            }

            @Override
            public MovementLocation location() {
                return MovementLocation.INSIDE;
            }
        };
    }

    static WindowProvider window(String uid) {
        return new WindowProvider() {
            @Override
            public String deviceUid() {
                return uid;
            }

            @Override
            public Connection connect(WindowListener listener) {
                return refused();
            }

            @Override
            public OpenState state() {
                return OpenState.CLOSED;
            }

            @Override
            public Optional<Coordinates> position() {
                return Optional.empty();
            }
        };
    }

    static PresenceProvider presence(String uid, PresenceKind kind) {
        return new PresenceProvider() {
            @Override
            public String deviceUid() {
                return uid;
            }

            @Override
            public Connection connect(PresenceListener listener) {
                return refused();
            }

            @Override
            public PresenceKind kind() {
                return kind;
            }

            @Override
            public boolean present() {
                return false;
            }
        };
    }
}
