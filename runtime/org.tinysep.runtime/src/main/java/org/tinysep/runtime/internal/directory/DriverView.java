package org.tinysep.runtime.internal.directory;

import java.util.List;
import org.tinysep.api.device.Parameter;

/**
 * What the shell shows of one driver.
 *
 * @param devices the driver's device count as text ({@code ?} if the driver failed to tell)
 * @param errors  calls into the driver that failed, one line each
 */
public record DriverView(String uid, String name, long bundleId, String devices, List<Parameter> parameters,
        List<String> errors) {
}
