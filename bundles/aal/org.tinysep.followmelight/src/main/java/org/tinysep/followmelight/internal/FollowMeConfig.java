package org.tinysep.followmelight.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of Follow Me Light (pid {@value FollowMeDriver#PID}). */
@ObjectClassDefinition(name = "Follow Me Light", description = "Lights follow the person from room to room.")
public @interface FollowMeConfig {

    @AttributeDefinition(description = "Seconds without motion in a lit room before its lights go off "
            + "(the multi-person wait of thesis 4.4.4.2)", min = "5", max = "3600")
    int graceSeconds() default 60;

    @AttributeDefinition(description = "Brightness in percent for dimmable lights switched on", min = "1",
            max = "100")
    int brightness() default 100;
}
