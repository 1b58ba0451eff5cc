package org.tinysep.followmelight.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.tinysep.api.actuator.DimmableLightListener;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightListener;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.sensor.PetMovementListener;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.service.FlatOccupancyListener;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.Placements;

/** Hand-written fakes of the API providers; every light command goes into one shared journal. */
final class Fakes {

    private Fakes() {
    }

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

    /** A simple light; {@link #confirm} plays the node's status report. */
    static final class Simple extends Base<SimpleLightListener> implements SimpleLightProvider {
        final List<String> journal;
        Boolean on;

        Simple(String uid, List<String> journal) {
            super(uid);
            this.journal = journal;
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

    static final class Dimmable extends Base<DimmableLightListener> implements DimmableLightProvider {
        final List<String> journal;
        Percent level;

        Dimmable(String uid, List<String> journal) {
            super(uid);
            this.journal = journal;
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

    static final class Movement extends Base<MovementListener> implements MovementProvider {
        Movement(String uid) {
            super(uid);
        }

        void report(Instant at) {
            List.copyOf(listeners).forEach(l -> l.movementReported(this, new MovementEvent(true, at)));
        }

        @Override
        public Optional<MovementEvent> lastMovement() {
            return Optional.empty();
        }

        @Override
        public MovementLocation location() {
            return MovementLocation.INSIDE;
        }
    }

    static final class Pet extends Base<PetMovementListener> implements PetMovementProvider {
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

    static final class Directory implements Placements {
        final Map<String, String> rooms = new HashMap<>();

        @Override
        public Optional<String> roomOf(String deviceUid) {
            return Optional.ofNullable(rooms.get(deviceUid));
        }

        @Override
        public String nameOf(String deviceUid) {
            return deviceUid;
        }
    }
}
