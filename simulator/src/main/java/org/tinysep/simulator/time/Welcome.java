package org.tinysep.simulator.time;

import java.time.Instant;

/** The platform's answer to HELLO: its time and clock mode ({@code REAL} or {@code EXTERNAL}). */
public record Welcome(Instant platformTime, String mode) {

    public boolean external() {
        return "EXTERNAL".equals(mode);
    }
}
