package org.tinysep.followmelight.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.actuator.DimmableLightListener;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightListener;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.sensor.PetMovementListener;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.testing.FakeFlat;
import org.tinysep.device.support.testing.FakeMovement;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.testing.FakeProvider;

/** Hand-written fakes of the API providers; every light command goes into one shared journal. */
final class Fakes {

    private Fakes() {
    }

    /**
     * A light: what the service asked of it goes to the journal ("uid on", "uid 40 %"); {@code state} is what the
     * node last reported (null before a report).
     *
     * @param <V> the reported state: on/off or a brightness
     */
    static class Light<L, V> extends FakeProvider<L> {
        final List<String> journal;
        V state;

        Light(String uid, List<String> journal) {
            super(uid);
            this.journal = journal;
        }

        final Optional<V> reported() {
            return Optional.ofNullable(state);
        }

        final void asked(Object what) {
            journal.add(uid + " " + what);
        }
    }

    /** A simple light; {@link #confirm} plays the node's status report. */
    static final class Simple extends Light<SimpleLightListener, Boolean> implements SimpleLightProvider {
        Simple(String uid, List<String> journal) {
            super(uid, journal);
        }

        @Override
        public void switchLight(boolean wanted) {
            asked(wanted ? "on" : "off");
        }

        @Override
        public Optional<Boolean> isOn() {
            return reported();
        }

        void confirm(boolean on, Instant at) {
            state = on;
            List.copyOf(listeners).forEach(l -> l.lightSwitched(this, on, at));
        }
    }

    static final class Dimmable extends Light<DimmableLightListener, Percent> implements DimmableLightProvider {
        Dimmable(String uid, List<String> journal) {
            super(uid, journal);
        }

        @Override
        public Optional<Percent> level() {
            return reported();
        }

        @Override
        public void setLevel(Percent b) {
            asked(b);
        }
    }

    static final class Movement extends FakeMovement {
        Movement(String uid) {
            super(uid);
        }
    }

    static final class Pet extends FakeProvider<PetMovementListener> implements PetMovementProvider {
        Pet(String uid) {
            super(uid);
        }

        void report(Instant at) {
            List.copyOf(listeners).forEach(l -> l.petMovementReported(this, new MovementEvent(true, at)));
        }

        @Override
        public Optional<MovementEvent> lastMovement() {
            return Optional.empty();
        }
    }

    static final class Flat extends FakeFlat {
        Flat(String uid, Occupancy occupancy, Instant since) {
            super(uid, occupancy, since);
        }
    }

    static final class Directory extends FakePlacements {
    }
}
