package org.tinysep.amica.busradio.udp.internal;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.DriverContext;

/**
 * Counts rejected datagrams per reason. The first rejection of each reason is logged (SLF4J warning and event
 * log); later ones are only counted, so a flood of garbage cannot flood the logs. Every rejected datagram is
 * still in the packet log with its reason.
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
     * @param message the reason and detail in the form of {@code AmicaProtocolException#getMessage()}
     */
    void reject(RejectReason reason, String message, String from) {
        if (counts.get(reason).incrementAndGet() == 1) {
            String text = "rejected datagram from " + from + ": " + message + "; further " + reason
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

    List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("rejected", total(), "datagrams rejected in total"));
        counts.forEach((r, n) -> out.add(Parameter.readOnly("rejected." + r.name().toLowerCase(), n.get(),
                r.description())));
        return out;
    }
}
