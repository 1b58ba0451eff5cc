package org.tinysep.sunspot.person.internal;

import java.time.Instant;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.ButtonAction;
import org.tinysep.api.sensor.person.ButtonEvent;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.ButtonReport;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotPayload;

/** One report of a person node, read from its payload and its arrival: what the device hands on or assembles. */
sealed interface PersonReport {

    /** A movement summary; the period ended at the frame's arrival. */
    record Summary(MovementSummary summary) implements PersonReport {
    }

    /** A switch pressed or released, at the frame's arrival. */
    record Button(ButtonEvent event) implements PersonReport {
    }

    /** One chunk of a burst and when it arrived: the device assembles the burst. */
    record Chunk(BurstChunk chunk, Instant at) implements PersonReport {
    }

    /**
     * @param payload a decoded payload of sensor type 6
     * @param at      its arrival
     * @return the report
     * @throws IllegalArgumentException if the payload is not a person node's (it came under the wrong header)
     */
    static PersonReport of(SunSpotPayload payload, Instant at) {
        if (payload instanceof MovementSummaryReport s) {
            return new Summary(new MovementSummary(at, java.time.Duration.ofMillis(s.spanMillis()),
                    acceleration(s.mean()), s.magnitudeSdMg(), s.peakMg()));
        }
        if (payload instanceof ButtonReport b) {
            return new Button(new ButtonEvent(b.button(), b.pressed() ? ButtonAction.PRESSED : ButtonAction.RELEASED,
                    at));
        }
        if (payload instanceof BurstChunk c) {
            return new Chunk(c, at);
        }
        throw new IllegalArgumentException("a person node frame carried " + payload.getClass().getSimpleName());
    }

    static Acceleration acceleration(AccelerationSample s) {
        return new Acceleration(s.xMg(), s.yMg(), s.zMg());
    }
}
