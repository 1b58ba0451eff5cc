package org.tinysep.amica.busradio.udp.internal;

import java.time.Duration;
import java.util.List;
import org.tinysep.device.support.delivery.OrderedDelivery;
import org.tinysep.device.support.lifecycle.DriverContext;

/** The UDP bus radio's ordered delivery: its settings and how long a lock-step tick waits for it. */
final class UdpDelivery {

    /** A tick waits at most this long for what was queued before it (past the slow-listener limit). */
    static final Duration TICK_WAIT = Duration.ofSeconds(2);
    static final int MIN_MILLIS = 100;
    static final int MAX_MILLIS = 60_000;

    private UdpDelivery() {
    }

    /** @param problems gets a plain-words line when {@code slowListenerMillis} is out of range (the default is used) */
    static OrderedDelivery open(DriverContext context, int slowListenerMillis, List<String> problems) {
        int millis = slowListenerMillis;
        if (millis < MIN_MILLIS || millis > MAX_MILLIS) {
            problems.add("slowListenerMillis = " + slowListenerMillis + " is outside " + MIN_MILLIS + " to "
                    + MAX_MILLIS + "; using " + OrderedDelivery.SLOW_CALL.toMillis() + " ms");
            millis = (int) OrderedDelivery.SLOW_CALL.toMillis();
        }
        return new OrderedDelivery(context, "The AmICA UDP radio", Duration.ofMillis(millis),
                OrderedDelivery.CAPACITY, OrderedDelivery.LANE_CAPACITY);
    }
}
