package org.tinysep.amica.busradio.base;

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
 * Counts rejected input per reason. The first rejection of each reason is logged (SLF4J warning and event log);
 * later ones are only counted, so a flood of garbage cannot flood the logs. Every rejected input is still in the
 * packet log with its reason ({@link FrameHandler} writes it).
 */
public final class RejectCounter {

    private static final Logger LOG = LoggerFactory.getLogger(RejectCounter.class);

    private final Map<RejectReason, AtomicLong> counts = new EnumMap<>(RejectReason.class);
    private final DriverContext context;
    private final String unit;
    private final String totalDescription;

    /**
     * @param unit             what one rejection is, for the log line "rejected {unit} from ...", e.g. {@code datagram}
     * @param totalDescription the description of the {@code rejected} parameter, e.g. "datagrams rejected in total"
     */
    public RejectCounter(DriverContext context, String unit, String totalDescription) {
        this.context = context;
        this.unit = unit;
        this.totalDescription = totalDescription;
        for (RejectReason r : RejectReason.values()) {
            counts.put(r, new AtomicLong());
        }
    }

    /**
     * Counts one rejection; logs it if it is the first of its reason.
     *
     * @param message the reason and detail in the form of {@code AmicaProtocolException#getMessage()}
     * @param from    where the input came from, e.g. {@code 127.0.0.1:5000} or {@code /dev/ttyUSB0}
     */
    public void reject(RejectReason reason, String message, String from) {
        if (counts.get(reason).incrementAndGet() == 1) {
            String text = "rejected " + unit + " from " + from + ": " + message + "; further " + reason
                    + " rejections are only counted";
            LOG.warn("{}: {}", context.driverName(), text);
            context.event(EventKind.PROBLEM, text);
        }
    }

    public long count(RejectReason reason) {
        return counts.get(reason).get();
    }

    public long total() {
        return counts.values().stream().mapToLong(AtomicLong::get).sum();
    }

    /** @return {@code rejected} (the total) and {@code rejected.<reason>} for every reason */
    public List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("rejected", total(), totalDescription));
        counts.forEach((r, n) -> out.add(Parameter.readOnly("rejected." + r.name().toLowerCase(), n.get(),
                r.description())));
        return out;
    }
}
