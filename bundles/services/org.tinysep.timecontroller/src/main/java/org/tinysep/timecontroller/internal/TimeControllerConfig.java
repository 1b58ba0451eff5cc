package org.tinysep.timecontroller.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;
import org.osgi.service.metatype.annotations.Option;

/** Configuration of the Time Controller (pid {@value TimeControllerDriver#PID}). */
@ObjectClassDefinition(name = "Time Controller",
        description = "The platform clock: real time, or driven in lock-step by a time synchroniser over UDP.")
public @interface TimeControllerConfig {

    @AttributeDefinition(description = "REAL follows the system clock; EXTERNAL moves only on TICKs of the "
            + "synchroniser (docs/time-sync.md). Changing it switches at once, without a restart.",
            options = {@Option(label = "real time", value = "REAL"), @Option(label = "external", value = "EXTERNAL")})
    String mode() default "REAL";

    @AttributeDefinition(description = "UDP port of the time synchroniser link; 0 picks a free port (published as "
            + "the Driver service property tinysep.sync.port)", min = "0", max = "65535")
    int syncPort() default 47020;

    @AttributeDefinition(description = "Local address the synchroniser link binds to; 0.0.0.0 listens on every "
            + "interface")
    String syncBindAddress() default "127.0.0.1";

    @AttributeDefinition(description = "File with the synchroniser's shared secret (TICK and BYE carry an HMAC made "
            + "with it). Empty: ${tinysep.var}/sync.key. A missing file is created with a random key, mode 0600.")
    String syncKeyFile() default "";

    @AttributeDefinition(description = "Seconds EXTERNAL time may go without a TICK before the clock returns to "
            + "REAL (the synchroniser has finished or gone); 0 never returns", min = "0")
    long syncTimeout() default 120;

    @AttributeDefinition(description = "Synchroniser addresses allowed when syncBindAddress is not a loopback "
            + "address: IP addresses or blocks, comma-separated; empty = 127.0.0.1 and ::1 only. Others are refused "
            + "(ERROR forbidden) and counted, so nobody else on the network can drive the clock")
    String syncAllowedSources() default "";
}
