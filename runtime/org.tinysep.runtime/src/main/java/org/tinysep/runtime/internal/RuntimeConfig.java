package org.tinysep.runtime.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the device manager, PID {@value #PID}. Out-of-range values are logged and ignored. */
@ObjectClassDefinition(name = "TinySEP device manager",
        description = "Capacities of the in-memory event log and packet log (oldest entries are dropped first).")
public @interface RuntimeConfig {

    String PID = "org.tinysep.runtime";

    @AttributeDefinition(name = "Event log capacity", min = "1", max = "5000000",
            description = "How many event-log entries are kept in memory.")
    int eventCapacity() default 10_000;

    @AttributeDefinition(name = "Packet log capacity", min = "1", max = "5000000",
            description = "How many packet-log entries are kept in memory.")
    int packetCapacity() default 20_000;
}
