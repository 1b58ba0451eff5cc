package org.tinysep.falldetection.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of Fall Detection (pid {@value FallDetection#PID}); defaults in {@link FallSettings#DEFAULT}. */
@ObjectClassDefinition(name = "Fall Detection",
        description = "A FALL alert when the worn person node reports a hard impact, then a changed posture and "
                + "stillness.")
public @interface FallDetectionConfig {

    @AttributeDefinition(description = "Peak acceleration of a burst that counts as an impact, milli-g", min = "1")
    int impactMg() default 2000;

    @AttributeDefinition(description = "Change of the body's orientation (mean acceleration before the impact "
            + "against the still period after it) that counts as a new posture, degrees", min = "0", max = "180")
    double postureChangeDegrees() default 30;

    @AttributeDefinition(description = "A movement summary whose magnitude SD is at most this is still, milli-g",
            min = "0")
    int stillSdMg() default 50;

    @AttributeDefinition(description = "Seconds the person must stay still after the impact", min = "1")
    int stillSeconds() default 6;

    @AttributeDefinition(description = "The stillness must begin within this many seconds after the impact",
            min = "1")
    int withinSeconds() default 20;

    @AttributeDefinition(description = "An impact when the body was already this far from the wearer's upright "
            + "(learned while they walk) is not a fall: they were lying already, turning over or getting up, "
            + "degrees; 180 = off", min = "0", max = "180")
    double alreadyLyingDegrees() default 70;

    @AttributeDefinition(description = "Time zone of the times in alerts, e.g. Europe/Berlin; empty = the system's")
    String timeZone() default "";
}
