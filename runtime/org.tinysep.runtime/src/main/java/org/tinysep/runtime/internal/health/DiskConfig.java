package org.tinysep.runtime.internal.health;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the disk watch, PID {@value #PID}. */
@ObjectClassDefinition(name = "TinySEP disk watch",
        description = "Watches the free space of the disk that holds the state folder; when it runs low, old log "
                + "files are deleted first and a PROBLEM is raised.")
public @interface DiskConfig {

    String PID = "org.tinysep.runtime.disk";

    @AttributeDefinition(name = "Minimum free space (MB)", min = "0",
            description = "Below this many free megabytes on the state folder's disk, old log files are deleted "
                    + "and a PROBLEM is raised. 0 switches the watch off.")
    long minFreeMegabytes() default 200;

    @AttributeDefinition(name = "Check interval (s)", min = "1",
            description = "How often the free space is checked.")
    int checkSeconds() default 60;
}
