package org.tinysep.launcher;

import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import org.osgi.framework.AllServiceListener;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceEvent;
import org.osgi.framework.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The caregiver signals recorded while TinySEP starts: the event log's {@code PROBLEM} entries
 * starting {@code Monitoring reduced: } or {@code Node type mismatch: } (a radio or console that cannot listen, a
 * watching application disabled) become one {@code WARNING: } line each under the banner, so "N/N bundles active"
 * is never all a deaf gateway says. The log's entries from before this start (its history) are left out: the
 * newest sequence number of the history is read from the log's files before the framework starts
 * ({@link EventHistoryEnd}); only when that cannot be told, it is taken when the event log registers (racy on a
 * loaded machine: the registration was seen after this start's first entries).
 * The launcher sees the log only by reflection (its classes live inside the framework).
 */
final class StartSignals {

    static final String EVENT_LOG = "org.tinysep.api.log.EventLog";
    static final List<String> PREFIXES = List.of("Monitoring reduced: ", "Node type mismatch: ");
    private static final Logger LOG = LoggerFactory.getLogger(StartSignals.class);

    private final BundleContext context;
    private final AtomicLong from = new AtomicLong(-1);
    /**
     * An AllServiceListener (the system bundle does not import the API): a plain ServiceListener was seen to be told
     * of the event log's registration only once 36 entries of this start had been recorded, which were then left
     * out as history (DeafRadioIT: no WARNING for a deaf radio); an AllServiceListener is told at the registration.
     */
    private final AllServiceListener listener;

    /** Starts watching for the event log; call before the framework starts. */
    StartSignals(BundleContext context) {
        this(context, -1);
    }

    /**
     * @param historyEnd the newest sequence number of the history, read from the files before the start
     *                   ({@link EventHistoryEnd}); -1: unknown, taken from the event log when it registers
     */
    StartSignals(BundleContext context, long historyEnd) {
        this.context = context;
        from.set(historyEnd);
        this.listener = (AllServiceListener) event -> {
            if (event.getType() == ServiceEvent.REGISTERED && from.get() < 0) {
                from.compareAndSet(-1, newest(event.getServiceReference()));
            }
        };
        try {
            context.addServiceListener(listener, "(objectClass=" + EVENT_LOG + ")");
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * @return one {@code WARNING: …} line per signal of this start, in order, without repeats (the web console starts
     *         on its first use, after the banner: the log says how that went)
     */
    List<String> warnings() {
        context.removeServiceListener(listener);
        return lines();
    }

    private List<String> lines() {
        Set<String> out = new LinkedHashSet<>();
        for (String message : signals()) {
            out.add("WARNING: " + message.substring(message.indexOf(": ") + 2));
        }
        return new ArrayList<>(out);
    }

    /** @return the messages of this start's signals, oldest first */
    private List<String> signals() {
        List<String> out = new ArrayList<>();
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(EVENT_LOG, null);
            if (refs == null) {
                return out;
            }
            Object log = context.getService(refs[0]);
            try {
                Class<?> type = refs[0].getBundle().loadClass(EVENT_LOG);
                List<?> entries = (List<?>) type.getMethod("recent", int.class).invoke(log, Integer.MAX_VALUE);
                long after = Math.max(0, from.get());
                for (Object e : entries) {
                    long seq = (Long) call(e, "sequence");
                    String kind = String.valueOf(call(e, "kind"));
                    String message = String.valueOf(call(e, "message"));
                    if (seq > after && "PROBLEM".equals(kind) && PREFIXES.stream().anyMatch(message::startsWith)) {
                        out.add(message);
                    }
                }
            } finally {
                context.ungetService(refs[0]);
            }
        } catch (Exception e) {
            LOG.debug("Cannot read the event log for the banner: {}", e.toString());
        }
        return out;
    }

    private long newest(ServiceReference<?> ref) {
        try {
            Object log = context.getService(ref);
            try {
                Class<?> type = ref.getBundle().loadClass(EVENT_LOG);
                List<?> last = (List<?>) type.getMethod("recent", int.class).invoke(log, 1);
                return last.isEmpty() ? 0 : (Long) call(last.get(0), "sequence");
            } finally {
                context.ungetService(ref);
            }
        } catch (Exception e) {
            LOG.debug("Cannot read the event log's newest entry: {}", e.toString());
            return 0;
        }
    }

    private static Object call(Object target, String method) throws ReflectiveOperationException {
        Method m = target.getClass().getMethod(method);
        return m.invoke(target);
    }
}
