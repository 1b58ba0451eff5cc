package org.tinysep.api.sensor;

/** Where a movement sensor watches (thesis A.3 movement type: inside or outside the house). */
public enum MovementLocation {
    INSIDE,
    OUTSIDE
}
