package org.tinysep.runtime.internal.backup;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the backup store (pid {@value BackupStoreService#PID}). */
@ObjectClassDefinition(name = "TinySEP backup store", description = "One XML file per driver and device (thesis 3.7).")
public @interface BackupConfig {

    @AttributeDefinition(description = "The backup folder. Empty: ${tinysep.var}/backup, else "
            + "${tinysep.home}/var/backup, else the bundle's data area")
    String folder() default "";

    @AttributeDefinition(description = "How long the writer waits after a save for more saves before it runs, "
            + "in milliseconds (saves of one component in that time become one write); BackupStore.flush, "
            + "which the shell's set waits for, writes at once")
    long writeDelayMillis() default 500;

    @AttributeDefinition(description = "An orderly stop saves every backup still queued first (a burst of new devices "
            + "can leave the writer thousands behind): a device's last state until this many seconds after the framework "
            + "began to stop, backups with no file yet this long after the store's own stop; kept below the launcher's "
            + "60 s stop limit")
    int stopSaveSeconds() default 25;

    @AttributeDefinition(description = "tinysep:restore refuses an archive that expands to more than this many bytes "
            + "(counted while it is read; default 64 MiB)")
    long restoreMaxBytes() default 64L << 20;

    @AttributeDefinition(description = "tinysep:restore refuses an archive with one file larger than this (bytes, "
            + "default 8 MiB)")
    long restoreMaxFileBytes() default 8L << 20;

    @AttributeDefinition(description = "tinysep:restore refuses an archive with more files than this")
    int restoreMaxFiles() default 10_000;
}
