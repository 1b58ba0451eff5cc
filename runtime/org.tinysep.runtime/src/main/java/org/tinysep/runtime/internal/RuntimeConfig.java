package org.tinysep.runtime.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the device manager, PID {@value #PID}. Out-of-range values are logged and ignored. */
@ObjectClassDefinition(name = "TinySEP device manager",
        description = "Capacities of the in-memory event log and packet log (oldest entries are dropped first) "
                + "and how their history is kept on disk.")
public @interface RuntimeConfig {

    String PID = "org.tinysep.runtime";

    @AttributeDefinition(name = "Event log capacity", min = "1", max = "5000000",
            description = "How many event-log entries are kept in memory.")
    int eventCapacity() default 10_000;

    @AttributeDefinition(name = "Packet log capacity", min = "1", max = "5000000",
            description = "How many packet-log entries are kept in memory.")
    int packetCapacity() default 20_000;

    @AttributeDefinition(name = "Keep log history on disk",
            description = "Write both logs to files, reload them on start and search them with tinysep:events "
                    + "and tinysep:packets. false: memory only.")
    boolean logPersistence() default true;

    @AttributeDefinition(name = "Log folder", description = "Folder of events-*.log and packets-*.log. Empty: "
            + "${tinysep.var}/log, else ${tinysep.home}/var/log, else the bundle's data area.")
    String logDirectory() default "";

    @AttributeDefinition(name = "Maximum log file size (KiB)", min = "1", max = "1048576",
            description = "A new file is started before one would grow beyond this.")
    int logMaxFileSizeKb() default 8192;

    @AttributeDefinition(name = "Maximum log files", min = "2", max = "10000",
            description = "Files kept per log (events, packets); the oldest are deleted first.")
    int logMaxFiles() default 16;

    @AttributeDefinition(name = "Log retention (days)", min = "0", max = "36500",
            description = "Files last written longer ago are deleted. 0: only the size bound applies.")
    int logRetentionDays() default 30;

    @AttributeDefinition(name = "Log sync interval (ms)", min = "10", max = "3600000",
            description = "How often written log entries are forced to the disk (fsync).")
    int logSyncMillis() default 2000;

    @AttributeDefinition(name = "Entries kept per origin", min = "0", max = "10000",
            description = "The newest entries of every node (and every other origin) kept beside the rotating "
                    + "files, so that a flood from other nodes cannot rotate them away. 0: none.")
    int logKeepPerOrigin() default 20;

    @AttributeDefinition(name = "Origins kept", min = "1", max = "100000",
            description = "At most this many nodes, and this many other origins, keep their newest entries; a new "
                    + "one replaces the least recently active of its group.")
    int logKeepOrigins() default 1000;
}
