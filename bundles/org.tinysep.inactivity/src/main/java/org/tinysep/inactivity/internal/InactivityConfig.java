package org.tinysep.inactivity.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of Inactivity Recognition (pid {@value InactivityDriver#PID}). */
@ObjectClassDefinition(name = "Inactivity Recognition",
        description = "Calls for help when nobody is active in a room for longer than its limit.")
public @interface InactivityConfig {

    @AttributeDefinition(description = "Minutes allowed after an activity in a room whose type has no limit, or "
            + "by a device that is not placed in a room", min = "1")
    int defaultLimitMinutes() default 120;

    @AttributeDefinition(description = "Limits per room type in minutes, e.g. 'Bathroom=45, Kitchen=90'")
    String typeLimits() default "Bathroom=45, Kitchen=90, Living room=180, Bedroom=600, Hall=30";

    @AttributeDefinition(description = "Overrides per room UID, room name or room type in minutes, "
            + "e.g. 'Bathroom=30, 6f1c...=20'")
    String roomLimits() default "";

    @AttributeDefinition(description = "Time zone for the times in alert mails, e.g. 'Europe/Berlin'; empty for "
            + "the system's")
    String timeZone() default "";
}
