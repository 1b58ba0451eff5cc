package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.tinysep.api.device.Connection;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.FlatOccupancyListener;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.Placements;

/** Hand-written fakes of the API providers the device consumes. */
final class Fakes {

    private Fakes() {
    }

    /** Listeners of one fake provider; a closed connection stops delivery. */
    static class Base<L> {
        final String uid;
        final List<L> listeners = new ArrayList<>();

        Base(String uid) {
            this.uid = uid;
        }

        public String deviceUid() {
            return uid;
        }

        public Connection connect(L l) {
            listeners.add(l);
            return new Connection() {
                @Override
                public void close() {
                    listeners.remove(l);
                }

                @Override
                public boolean isOpen() {
                    return listeners.contains(l);
                }
            };
        }
    }

    static final class Movement extends Base<MovementListener> implements MovementProvider {
        MovementLocation location = MovementLocation.INSIDE;

        Movement(String uid) {
            super(uid);
        }

        void report(boolean detected, Instant at) {
            List.copyOf(listeners).forEach(l -> l.movementReported(this, new MovementEvent(detected, at)));
        }

        @Override
        public Optional<MovementEvent> lastMovement() {
            return Optional.empty();
        }

        @Override
        public MovementLocation location() {
            return location;
        }
    }

    static final class Door extends Base<DoorListener> implements DoorProvider {
        private volatile OpenState state = OpenState.UNKNOWN;

        Door(String uid) {
            super(uid);
        }

        /** Like a door device: a change (or the first report, {@code first}) is heard, a repeat is not. */
        void change(OpenState s, Instant at) {
            if (s == state) {
                return;
            }
            boolean first = state == OpenState.UNKNOWN;
            state = s;
            List.copyOf(listeners).forEach(l -> l.doorChanged(this, s, first, at));
        }

        @Override
        public OpenState state() {
            return state;
        }

        @Override
        public DoorKind kind() {
            return DoorKind.INNER;
        }
    }

    static final class Flat extends Base<FlatOccupancyListener> implements FlatOccupancyProvider {
        Occupancy occupancy;
        Instant since;

        Flat(String uid, Occupancy occupancy, Instant since) {
            super(uid);
            this.occupancy = occupancy;
            this.since = since;
        }

        void change(Occupancy o, Instant at) {
            occupancy = o;
            since = at;
            List.copyOf(listeners).forEach(l -> l.occupancyChanged(this, o, at));
        }

        @Override
        public Occupancy occupancy() {
            return occupancy;
        }

        @Override
        public Instant since() {
            return since;
        }
    }

    static final class Mail extends Base<MailManagerListener> implements MailManagerProvider {
        final List<String> sent = new ArrayList<>();

        Mail(String uid) {
            super(uid);
        }

        @Override
        public void send(String subject, String body) {
            sent.add(subject + "\n" + body);
        }

        @Override
        public MailStatus status() {
            return MailStatus.IDLE;
        }
    }

    /** Rooms and names kept in maps; a test moves a device by changing the map. */
    static final class Directory implements Placements {
        final Map<String, String> rooms = new HashMap<>();
        final Map<String, String> names = new HashMap<>();

        @Override
        public Optional<String> roomOf(String deviceUid) {
            return Optional.ofNullable(rooms.get(deviceUid));
        }

        @Override
        public String nameOf(String deviceUid) {
            return names.getOrDefault(deviceUid, deviceUid);
        }
    }
}
