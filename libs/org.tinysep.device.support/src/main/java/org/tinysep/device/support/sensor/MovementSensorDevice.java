package org.tinysep.device.support.sensor;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * A person's movement sensor: a {@link MotionSensorDevice} that watches INSIDE (default) or OUTSIDE the flat, the
 * writable parameter {@code location}; listeners hear a change as {@code locationChanged}, the event log as
 * "location set to OUTSIDE".
 *
 * @param <V> the reading: a {@link MovementEvent}, or one that carries one
 */
public abstract class MovementSensorDevice<V> extends MotionSensorDevice<MovementListener, V>
        implements MovementProvider {

    private volatile MovementLocation location = MovementLocation.INSIDE;

    protected MovementSensorDevice(DriverContext context, Source<V> source, String nodeType, String name,
            Function<V, MovementEvent> event, Class<?>... provides) {
        super(context, source, nodeType, name, event, "movement detected", "no movement", provides);
    }

    @Override
    public final MovementLocation location() {
        return location;
    }

    @Override
    protected final List<Parameter> settings() {
        return List.of(Parameter.writable("location", location, "INSIDE or OUTSIDE the flat"));
    }

    @Override
    protected final void applyParameter(String key, String value) {
        if (!"location".equals(key)) {
            throw unknownParameter(key);
        }
        MovementLocation l;
        try {
            l = MovementLocation.valueOf(value.strip().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException | NullPointerException e) {
            throw new IllegalArgumentException("location must be INSIDE or OUTSIDE, was '" + value + "'");
        }
        location = l;
        event("location set to " + l);
        Instant at = now();
        fire(x -> x.locationChanged(this, l, at));
    }
}
