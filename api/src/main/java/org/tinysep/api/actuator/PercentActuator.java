package org.tinysep.api.actuator;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.sensor.Percent;

/**
 * What the percent actuators share (since 2.0): a level from 0 to 100 % that the node reports and that a request
 * changes only once the node's next status report confirms it. It is a dimmable light's brightness, a heater's
 * potency, a speaker's volume ({@link DimmableLightProvider}, {@link HeaterProvider}, {@link SpeakerProvider}); their
 * listeners still name it ({@code brightnessChanged}, {@code potencyChanged}, {@code volumeChanged}).
 */
@ProviderType
public interface PercentActuator {

    /** @return the level the node last reported; empty before its first report */
    Optional<Percent> level();

    /** Asks the node for a new level; returns at once, listeners hear it when the node's next report confirms it. */
    void setLevel(Percent level);
}
