package org.tinysep.device.support.testing;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;

/** A movement sensor for unit tests of services: {@link #report} plays a report; INSIDE unless told. */
public class FakeMovement extends FakeProvider<MovementListener> implements MovementProvider {

    public MovementLocation location = MovementLocation.INSIDE;

    public FakeMovement(String uid) {
        super(uid);
    }

    /** Plays a motion report. */
    public void report(Instant at) {
        report(true, at);
    }

    public void report(boolean detected, Instant at) {
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
