package org.tinysep.runtime.internal.directory;

import org.tinysep.api.device.Driver;

/**
 * A tracked {@link Driver} service.
 *
 * @param serviceId  the service.id of its registration
 * @param uid        {@link Driver#uid()} as read when it appeared
 * @param name       {@link Driver#name()} as read when it appeared
 * @param bundleId   the bundle that registered it
 * @param bundleName that bundle's symbolic name
 * @param driver     the service object
 */
public record DriverRecord(long serviceId, String uid, String name, long bundleId, String bundleName,
        Driver driver) {

    public DriverRecord {
        uid = uid == null ? "" : uid;
        name = name == null || name.isEmpty() ? uid : name;
        bundleName = bundleName == null ? "" : bundleName;
    }
}
