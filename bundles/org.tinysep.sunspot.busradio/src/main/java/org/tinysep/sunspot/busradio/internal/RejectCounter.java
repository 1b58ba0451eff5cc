package org.tinysep.sunspot.busradio.internal;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.DriverContext;
import org.tinysep.sunspot.protocol.RejectReason;

/**
 * Counts rejected input per reason. The first rejection of each reason is logged (SLF4J warning and event log);
 * later ones are only counted, so a flood of garbage cannot flood the logs. Every rejected input is still in the
 * packet log with its reason ({@link PacketHandler} writes it). Thread-safe: all links report here.
 */
final class RejectCounter {

    private static final Logger LOG = LoggerFactory.getLogger(RejectCounter.class);

    private final Map<RejectReason, AtomicLong> counts = new EnumMap<>(RejectReason.class);
    private final DriverContext context;

    RejectCounter(DriverContext context) {
        this.context = context;
        for (RejectReason r : RejectReason.values()) {
            counts.put(r, new AtomicLong());
        }
    }

    /**
     * Counts one rejection; logs it if it is the first of its reason.
     *
     * @param message the reason and detail in the form of {@code SunSpotProtocolException#getMessage()}
     * @param from    where the input came from, e.g. {@code udp 127.0.0.1:5000} or {@code serial /dev/ttyUSB0}
     */
    void reject(RejectReason reason, String message, String from) {
        if (counts.get(reason).incrementAndGet() == 1) {
            String text = "rejected packet from " + from + ": " + message + "; further " + reason
                    + " rejections are only counted";
            LOG.warn("{}: {}", context.driverName(), text);
            context.event(EventKind.PROBLEM, text);
        }
    }

    long count(RejectReason reason) {
        return counts.get(reason).get();
    }

    long total() {
        return counts.values().stream().mapToLong(AtomicLong::get).sum();
    }

    /** @return {@code rejected} (the total) and {@code rejected.<reason>} for every reason */
    List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("rejected", total(), "packets (or serial byte runs) rejected in total"));
        counts.forEach((r, n) -> out.add(Parameter.readOnly("rejected." + r.name().toLowerCase(Locale.ROOT),
                n.get(), r.description())));
        return out;
    }
}
