package org.tinysep.device.support.testing;

import java.time.Instant;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * The platform side of a device's unit test, written once: a clock fixed at {@link #T0}, the logs recorded on it
 * ({@link #logs}) and the {@link DriverContext} a driver hands its devices ({@link #context}), without a framework.
 * Never referenced by main code, so bnd never copies it into a bundle.
 */
public final class TestPlatform {

    /** The fixed platform time of the test. */
    public static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    /** The events and problems the device reported. */
    public final RecordingLogs logs = new RecordingLogs(() -> T0);

    /** @return the context of a driver named {@code driverName} on this platform */
    public DriverContext context(String driverName) {
        return new DriverContext(null, "d", driverName, logs.reporter(), new PlatformClock(() -> T0));
    }
}
