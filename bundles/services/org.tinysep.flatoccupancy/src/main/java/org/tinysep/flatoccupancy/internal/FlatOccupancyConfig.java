package org.tinysep.flatoccupancy.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of Flat Occupancy (pid {@value FlatOccupancyDriver#PID}). */
@ObjectClassDefinition(name = "Flat Occupancy", description = "Decides whether someone is in the flat.")
public @interface FlatOccupancyConfig {

    @AttributeDefinition(description = "Seconds without indoor motion after the outer door closed before the flat "
            + "counts as empty", min = "10", max = "86400")
    int leaveTimeoutSeconds() default 600;

    @AttributeDefinition(description = "Seconds after the outer door closed during which motion is ignored "
            + "(the leaving person is still seen by the hall sensor)", min = "0", max = "300")
    int exitGraceSeconds() default 10;
}
