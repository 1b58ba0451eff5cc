package org.tinysep.houseinformation.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the room placement by node address (pid {@value RoomPlacer#PID}). */
@ObjectClassDefinition(name = "House Information room placement",
        description = "Places devices in rooms by their node address when they appear.")
public @interface PlacementConfig {

    @AttributeDefinition(description = "Comma- or newline-separated entries <node address>=<room name or UID>, "
            + "e.g. 1.10=Hall, 0014.4F01.0000.0001=Kitchen. Empty: no automatic placement")
    String placements() default "";
}
