package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.testing.FakeFlat;
import org.tinysep.device.support.testing.FakeMovement;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.testing.FakeProvider;

/** Hand-written fakes of the API providers the device consumes. */
final class Fakes {

    private Fakes() {
    }

    /** Listeners of one fake provider; a closed connection stops delivery. */
    static class Base<L> extends FakeProvider<L> {
        Base(String uid) {
            super(uid);
        }
    }

    static final class Movement extends FakeMovement {
        Movement(String uid) {
            super(uid);
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

    static final class Flat extends FakeFlat {
        Flat(String uid, Occupancy occupancy, Instant since) {
            super(uid, occupancy, since);
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
    static final class Directory extends FakePlacements {
    }
}
