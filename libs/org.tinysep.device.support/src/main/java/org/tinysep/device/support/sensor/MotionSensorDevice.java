package org.tinysep.device.support.sensor;

import java.util.List;
import java.util.Optional;
import java.util.function.Function;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * A movement sensor, of a person or of a pet: every report goes to the listeners, motion or not; only changes
 * (motion / no motion) are written to the event log. The read-only parameter {@code lastMovement} shows the last
 * report.
 *
 * @param <L> the listener interface
 * @param <V> the reading: a {@link MovementEvent}, or one that carries one (e.g. with coordinates)
 */
public abstract class MotionSensorDevice<L, V> extends SensorDevice<L, V> {

    private final Function<V, MovementEvent> event;
    private final String moving;
    private final String still;

    /**
     * @param event  the movement event of a reading ({@code Function.identity()} for a {@code MovementEvent})
     * @param moving the event-log entry for motion, e.g. "movement detected"
     * @param still  the entry for no motion any more, e.g. "no movement"
     */
    protected MotionSensorDevice(DriverContext context, Source<V> source, String nodeType, String name,
            Function<V, MovementEvent> event, String moving, String still, Class<?>... provides) {
        super(context, source, nodeType, name, provides);
        this.event = event;
        this.moving = moving;
        this.still = still;
    }

    /** @return whether the reading says motion */
    protected final boolean detected(V reading) {
        return event.apply(reading).detected();
    }

    @Override
    protected final boolean isChange(V before, V now) {
        return detected(before) != detected(now);
    }

    @Override
    protected String describe(V reading) {
        return detected(reading) ? moving : still;
    }

    @Override
    protected final boolean tellsEveryReport() {
        return true;
    }

    /** @return the last report, empty before the first (implements the providers' {@code lastMovement()}) */
    public final Optional<MovementEvent> lastMovement() {
        return Optional.ofNullable(latest()).map(event);
    }

    @Override
    protected List<Parameter> readings() {
        MovementEvent e = lastMovement().orElse(null);
        return List.of(Parameter.readOnly("lastMovement",
                e == null ? "" : (e.detected() ? "motion at " : "none at ") + e.at(), "last report"));
    }
}
