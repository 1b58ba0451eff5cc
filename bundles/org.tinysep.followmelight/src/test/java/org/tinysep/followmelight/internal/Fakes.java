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

    /** A light: what the service asked of it goes to the journal ("uid on", "uid 40 %"). */
    static class Light<L> extends FakeProvider<L> {
        final List<String> journal;

        Light(String uid, List<String> journal) {
            super(uid);
            this.journal = journal;
        }
    }

    /** A simple light; {@link #confirm} plays the node's status report. */
    static final class Simple extends Light<SimpleLightListener> implements SimpleLightProvider {
        Boolean on;

        Simple(String uid, List<String> journal) {
            super(uid, journal);
        }

        @Override
        public Optional<Boolean> isOn() {
            return Optional.ofNullable(on);
        }

        @Override
        public void switchLight(boolean wanted) {
            journal.add(uid + (wanted ? " on" : " off"));
        }

        void confirm(boolean state, Instant at) {
            on = state;
            List.copyOf(listeners).forEach(l -> l.lightSwitched(this, state, at));
        }
    }

    static final class Dimmable extends Light<DimmableLightListener> implements DimmableLightProvider {
        Percent level;

        Dimmable(String uid, List<String> journal) {
            super(uid, journal);
        }

        @Override
        public Optional<Percent> brightness() {
            return Optional.ofNullable(level);
        }

        @Override
        public void setBrightness(Percent b) {
            journal.add(uid + " " + b);
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
