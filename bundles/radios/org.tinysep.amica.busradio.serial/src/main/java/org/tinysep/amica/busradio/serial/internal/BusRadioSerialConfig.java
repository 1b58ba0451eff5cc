package org.tinysep.amica.busradio.serial.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/**
 * One serial port of the Bus Radio AmICA (factory pid {@value AmicaSerialDriver#PID}): each configuration is one
 * port and one driver instance.
 */
@ObjectClassDefinition(name = "Bus Radio AmICA (serial)",
        description = "AmICA nodes through the modified AmICA base node on a serial port; one configuration per port.")
public @interface BusRadioSerialConfig {

    @AttributeDefinition(description = "Serial port path, e.g. /dev/ttyUSB0 or a /dev/serial/by-id/... link")
    String port();

    @AttributeDefinition(description = "Baud rate (8 data bits, no parity, 1 stop bit, no flow control)")
    int baudRate() default SerialSettings.DEFAULT_BAUD_RATE;

    @AttributeDefinition(description = "Seconds between attempts to open a missing or lost port")
    int reopenSeconds() default SerialSettings.DEFAULT_REOPEN_SECONDS;

    @AttributeDefinition(description = "Report intervals without a valid frame after which a node is OFFLINE")
    int silentAfterIntervals() default 30;

    @AttributeDefinition(description = "Keep-alive battery voltage (mV) below which a node's battery is reported "
            + "low; 0 = never")
    int lowBatteryMillivolts() default 2200;

    @AttributeDefinition(description = "Most nodes this port's bus radio creates; keep-alives of further new nodes "
            + "are rejected and counted")
    int maxNodes() default 1000;
}
