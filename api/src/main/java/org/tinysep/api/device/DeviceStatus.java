package org.tinysep.api.device;

import java.time.Instant;
import java.util.Objects;

/**
 * Status of a device or driver, with a human-readable detail (e.g. "no packet for 300 s", "port vanished").
 *
 * @param state  the coarse state
 * @param detail a sentence for the user; empty when there is nothing to add
 * @param since  when the state was entered
 */
public record DeviceStatus(State state, String detail, Instant since) {

    /** Coarse states, in the spirit of openHAB's thing status. */
    public enum State {
        /** Working and recently heard from. */
        ONLINE,
        /** Not heard from, or its hardware link is down; it may come back by itself. */
        OFFLINE,
        /** Not yet known (e.g. created, no data yet). */
        UNKNOWN,
        /** Misconfigured or failing; needs the user's attention. */
        ERROR
    }

    public DeviceStatus {
        Objects.requireNonNull(state, "state");
        detail = detail == null ? "" : detail;
        Objects.requireNonNull(since, "since");
    }

    public static DeviceStatus online(Instant since) {
        return new DeviceStatus(State.ONLINE, "", since);
    }

    @Override
    public String toString() {
        return detail.isEmpty() ? state.name() : state + " (" + detail + ")";
    }
}
