package org.tinysep.runtime.internal.directory;

import java.util.List;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.Parameter;

/**
 * What the shell shows of one device, read live from the device and the inventory.
 *
 * @param driverName the owning driver's name, or {@code ?<driverUid>} when no tracked driver has that UID
 * @param errors     calls into the device that failed, one line each
 */
public record DeviceView(String uid, String type, String name, String status, String driverName,
        List<String> provides, List<ConnectionInfo> connections, NodeInfo node, List<Parameter> parameters,
        List<DeviceFunction> functions, List<String> errors) {
}
