package org.tinysep.api.sensor.person;

import org.osgi.annotation.versioning.ConsumerType;

/** Receives a person node's reports. Each method returns quickly (the radio's thread calls it). */
@ConsumerType
public interface PersonNodeListener {

    /** A movement summary arrived (every summary period while the node is on). */
    default void movementSummarised(PersonNodeProvider source, MovementSummary summary) {
    }

    /** The raw samples around an acceleration peak arrived, complete. */
    default void burstReceived(PersonNodeProvider source, AccelerationBurst burst) {
    }

    /** A switch was pressed or released. */
    default void buttonChanged(PersonNodeProvider source, ButtonEvent event) {
    }
}
