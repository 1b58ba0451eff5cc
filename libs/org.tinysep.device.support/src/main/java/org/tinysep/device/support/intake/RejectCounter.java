package org.tinysep.device.support.intake;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * Counts a radio's rejected input per reason, for any protocol family's reason enum. The first rejection of each
 * reason is logged (SLF4J warning and a {@code PROBLEM} in the event log); later ones are only counted, so a flood of
 * garbage cannot flood the logs. Thread-safe: every link of a radio reports here. The rejected input itself goes to
 * the packet log through the radio's own handler.
 *
 * @param <R> the family's reject reasons
 */
public final class RejectCounter<R extends Enum<R>> {

    private static final Logger LOG = LoggerFactory.getLogger(RejectCounter.class);

    private final Map<R, AtomicLong> counts;
    private final DriverContext context;
    private final Function<R, String> describe;
    private final String unit;
    private final String totalDescription;

    /**
     * @param reasons          the family's reason enum
     * @param describe         a reason's rule in plain words (the {@code rejected.<reason>} parameter's description)
     * @param unit             what one rejection is, for "rejected {unit} from ...", e.g. {@code datagram}
     * @param totalDescription the description of the {@code rejected} parameter, e.g. "datagrams rejected in total"
     */
    public RejectCounter(DriverContext context, Class<R> reasons, Function<R, String> describe, String unit,
            String totalDescription) {
        this.context = Objects.requireNonNull(context, "context");
        this.describe = Objects.requireNonNull(describe, "describe");
        this.unit = Objects.requireNonNull(unit, "unit");
        this.totalDescription = Objects.requireNonNull(totalDescription, "totalDescription");
        this.counts = new EnumMap<>(reasons);
        for (R r : reasons.getEnumConstants()) {
            counts.put(r, new AtomicLong());
        }
    }

    /**
     * Counts one rejection; logs it if it is the first of its reason.
     *
     * @param message the reason and detail, as the family's protocol exception words it
     * @param from    where the input came from, e.g. {@code udp 127.0.0.1:5000} or {@code serial /dev/ttyUSB0}
     */
    public void reject(R reason, String message, String from) {
        if (counts.get(reason).incrementAndGet() == 1) {
            String text = "rejected " + unit + " from " + from + ": " + message + "; further " + reason
                    + " rejections are only counted";
            LOG.warn("{}: {}", context.driverName(), text);
            context.event(EventKind.PROBLEM, text);
        }
    }

    public long count(R reason) {
        return counts.get(reason).get();
    }

    public long total() {
        return counts.values().stream().mapToLong(AtomicLong::get).sum();
    }

    /** @return {@code rejected} (the total) and {@code rejected.<reason>} for every reason */
    public List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("rejected", total(), totalDescription));
        counts.forEach((r, n) -> out.add(Parameter.readOnly("rejected." + r.name().toLowerCase(Locale.ROOT),
                n.get(), describe.apply(r))));
        return out;
    }
}
