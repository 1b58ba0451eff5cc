package org.tinysep.inactivity.internal;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.api.sensor.OpenState;

/**
 * The last known state of each door and window contact, so that only a change a person made counts as activity.
 * A contact's first report after it (or its device) starts — a node powering up, the platform restarting — only
 * tells its state: counting it would make every restart look like activity in every room with a door or window,
 * and would move an unanswered bathroom alert's clock to another room.
 */
final class ContactStates {

    private final Map<String, OpenState> last = new ConcurrentHashMap<>();

    /** The state a contact already had when it was connected ({@code UNKNOWN} before its first report). */
    void connected(String deviceUid, OpenState current) {
        last.putIfAbsent(deviceUid, current);
    }

    /**
     * @return true if {@code state} is a change from a known open/closed state; false for a first report, a repeat
     *         or {@code UNKNOWN}
     */
    boolean isChange(String deviceUid, OpenState state) {
        OpenState before = last.put(deviceUid, state);
        return state != OpenState.UNKNOWN && before != null && before != OpenState.UNKNOWN && before != state;
    }
}
