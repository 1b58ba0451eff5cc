package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.service.InactivityState;

/**
 * What the parts of the Inactivity Recognition device ({@link StateAnnouncer}, {@link ActivityFeed},
 * {@link LoggedHistory}) ask of the device itself: its event log entries, its backup, its status and its listeners.
 *
 * @param events  an event log entry of the device, in plain words
 * @param saving  saves the device's state now (a change that must survive a crash)
 * @param changes the state changed in a way that is saved at most every 10 s (docs/backup.md)
 * @param status  the device's status and its reason
 * @param fire    tells the device's listeners that the state changed
 */
record DeviceSide(Consumer<String> events, Runnable saving, Runnable changes,
        BiConsumer<DeviceStatus.State, String> status, BiConsumer<InactivityState, Instant> fire) {

    void event(String message) {
        events.accept(message);
    }

    void save() {
        saving.run();
    }

    void changed() {
        changes.run();
    }

    /** The device works as it should (status ONLINE). */
    void online() {
        status.accept(DeviceStatus.State.ONLINE, "");
    }

    /** The device cannot do its job: status ERROR with the reason. */
    void error(String detail) {
        status.accept(DeviceStatus.State.ERROR, detail);
    }

    void fire(InactivityState state, Instant at) {
        fire.accept(state, at);
    }
}
