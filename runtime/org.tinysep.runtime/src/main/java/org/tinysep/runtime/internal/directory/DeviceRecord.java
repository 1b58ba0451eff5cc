package org.tinysep.runtime.internal.directory;

import org.tinysep.api.device.Device;

/**
 * A tracked {@link Device} service. Identity fields are read once when it appears; the node information follows
 * property changes of the registration.
 *
 * @param serviceId the service.id of its registration
 * @param uid       its device UID
 * @param type      its type
 * @param name      its name when it appeared
 * @param driverUid the UID of the driver that owns it (service property, else {@link Device#driverUid()})
 * @param node      node types, address and room from the service properties
 * @param device    the service object
 */
public record DeviceRecord(long serviceId, String uid, String type, String name, String driverUid, NodeInfo node,
        Device device) {

    public DeviceRecord {
        uid = uid == null ? "" : uid;
        type = type == null ? "" : type;
        name = name == null ? "" : name;
        driverUid = driverUid == null ? "" : driverUid;
        node = node == null ? NodeInfo.NONE : node;
    }

    DeviceRecord withNode(NodeInfo newNode) {
        return new DeviceRecord(serviceId, uid, type, name, driverUid, newNode, device);
    }
}
