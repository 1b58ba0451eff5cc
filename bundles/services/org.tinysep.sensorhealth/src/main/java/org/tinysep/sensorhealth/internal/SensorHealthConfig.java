package org.tinysep.sensorhealth.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of Sensor Health (pid {@value SensorHealthDriver#PID}). */
@ObjectClassDefinition(name = "Sensor Health",
        description = "Notices to caregivers when a sensor falls silent or its battery runs low; unmonitored rooms.")
public @interface SensorHealthConfig {

    @AttributeDefinition(description = "Minutes a sensor must stay OFFLINE before a caregiver gets a notice (a "
            + "sensor back sooner sends none); 0 = at once", min = "0")
    int noticeAfterMinutes() default 10;

    @AttributeDefinition(description = "Mail notices through the Mail Manager; false = event log only")
    boolean mailNotices() default true;

    @AttributeDefinition(description = "Time zone of the times in notices, e.g. Europe/Berlin; empty = the system's")
    String timeZone() default "";
}
