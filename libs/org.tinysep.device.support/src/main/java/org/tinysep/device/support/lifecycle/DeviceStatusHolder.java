package org.tinysep.device.support.lifecycle;

import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;

/** A device's status: {@code UNKNOWN} until it says otherwise; each change is recorded in the event log. */
final class DeviceStatusHolder {

    private final DriverContext context;
    private final String uid;
    private volatile DeviceStatus status;

    DeviceStatusHolder(DriverContext context, String uid) {
        this.context = context;
        this.uid = uid;
        this.status = new DeviceStatus(DeviceStatus.State.UNKNOWN, "", context.now());
    }

    DeviceStatus get() {
        return status;
    }

    void set(DeviceStatus.State state, String detail) {
        DeviceStatus old = status;
        if (old.state() == state && old.detail().equals(detail == null ? "" : detail)) {
            return;
        }
        status = new DeviceStatus(state, detail, context.now());
        context.reporter().event(EventKind.STATUS, uid, "status " + status);
    }
}
