package org.tinysep.device.support.lifecycle;

import java.lang.reflect.Method;
import java.util.Collection;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceEvent;
import org.osgi.framework.ServiceRegistration;
import org.osgi.framework.UnfilteredServiceListener;
import org.osgi.framework.hooks.service.EventListenerHook;
import org.osgi.framework.hooks.service.ListenerHook.ListenerInfo;

/**
 * Spares the framework the service listeners that cannot want an event (issue 29, item 4). Felix hands every
 * service event to every service listener of the framework and evaluates each one's filter: with ~250 listeners
 * (each driver's trackers of the event log, clock, rooms and backup store; the Declarative Services references) a
 * device's registration cost ~400 µs of filter matching, 55 % of creating a device (JFR), for the dozen listeners
 * that care. This hook removes, before that, each listener whose filter names an {@code objectClass} the service
 * does not have: a listener whose filter is {@code (objectClass=X)} or an AND with such a term, as a
 * {@code ServiceTracker} of a class and Declarative Services register them. What a listener's filter says is worked
 * out once per listener (by identity), so an event costs one look-up per listener instead of a filter match.
 * <p>
 * Never removes a listener the framework would have called: {@code objectClass} cannot change, so such a listener
 * matched neither the old nor the new properties of a modified service; a filter it cannot read for certain
 * (wildcards, escapes, OR, NOT, white space, no filter) and an {@link UnfilteredServiceListener} (on Felix, whose
 * listener infos name their listener) are kept.
 */
public final class ListenerPruning implements EventListenerHook {

    /** A filter's required classes: the service must have every one; {@link #ANY} when it cannot be told. */
    private static final String[] ANY = new String[0];
    /** Listener infos remembered at most; more (listeners come and go) starts the memory afresh. */
    private static final int REMEMBERED = 4_096;

    /** The required classes of each listener info seen, by identity; guarded by itself. */
    private final IdentityHashMap<ListenerInfo, String[]> known = new IdentityHashMap<>();
    private final LongAdder kept = new LongAdder();
    private final LongAdder removed = new LongAdder();

    /** Registers this hook with the framework, before any other hook; unregister it to stop pruning. */
    public ServiceRegistration<EventListenerHook> register(BundleContext context) {
        Dictionary<String, Object> props = new Hashtable<>();
        props.put(Constants.SERVICE_RANKING, Integer.MAX_VALUE); // first, so later hooks see fewer listeners
        return context.registerService(EventListenerHook.class, this, props);
    }

    @Override
    public void event(ServiceEvent event, Map<BundleContext, Collection<ListenerInfo>> listeners) {
        Object classes = event.getServiceReference().getProperty(Constants.OBJECTCLASS);
        if (!(classes instanceof String[] has)) {
            return;
        }
        for (Collection<ListenerInfo> infos : listeners.values()) {
            int before = infos.size();
            infos.removeIf(info -> !mayWant(required(info), has));
            removed.add(before - infos.size());
            kept.add(infos.size());
        }
    }

    /** @return how many listeners this hook left to the framework since it was made, over all events */
    public long kept() {
        return kept.sum();
    }

    /** @return how many listeners this hook spared the framework since it was made, over all events */
    public long removed() {
        return removed.sum();
    }

    private static boolean mayWant(String[] required, String[] has) {
        for (String r : required) {
            if (!contains(has, r)) {
                return false;
            }
        }
        return true;
    }

    private static boolean contains(String[] has, String name) {
        for (String h : has) {
            if (h.equals(name)) {
                return true;
            }
        }
        return false;
    }

    private String[] required(ListenerInfo info) {
        synchronized (known) {
            String[] r = known.get(info);
            if (r == null) {
                if (known.size() >= REMEMBERED) {
                    known.clear(); // listeners of the past: worked out again when seen
                }
                r = unfiltered(info) ? ANY : requiredClasses(info.getFilter());
                known.put(info, r);
            }
            return r;
        }
    }

    /** @return whether the listener takes every event whatever its filter; true when that cannot be told */
    private static boolean unfiltered(ListenerInfo info) {
        try {
            Method m = info.getClass().getMethod("getListener"); // Felix's listener info names its listener
            return m.invoke(info) instanceof UnfilteredServiceListener;
        } catch (ReflectiveOperationException | RuntimeException e) {
            return true; // another framework: keep every listener
        }
    }

    /**
     * @return the classes a service must have to match {@code filter}: from {@code (objectClass=X)} or the
     *         {@code (objectClass=X)} terms of a top-level AND; {@link #ANY} for anything else
     */
    static String[] requiredClasses(String filter) {
        if (filter == null || filter.indexOf('\\') >= 0) {
            return ANY;
        }
        String one = objectClassTerm(filter);
        if (one != null) {
            return new String[] {one};
        }
        if (!filter.startsWith("(&(") || !filter.endsWith(")")) {
            return ANY;
        }
        java.util.List<String> out = new java.util.ArrayList<>();
        int depth = 0;
        int start = -1;
        for (int i = 2; i < filter.length() - 1; i++) {
            char c = filter.charAt(i);
            if (c == '(') {
                if (depth++ == 0) {
                    start = i;
                }
            } else if (c == ')') {
                if (--depth == 0) {
                    String term = objectClassTerm(filter.substring(start, i + 1));
                    if (term != null) {
                        out.add(term);
                    }
                } else if (depth < 0) {
                    return ANY;
                }
            }
        }
        return depth == 0 ? out.toArray(ANY) : ANY;
    }

    /** @return X when {@code term} is exactly {@code (objectClass=X)} with a plain X; null otherwise */
    private static String objectClassTerm(String term) {
        String key = "(" + Constants.OBJECTCLASS + "=";
        if (term.length() <= key.length() + 1 || !term.regionMatches(true, 0, key, 0, key.length())
                || !term.endsWith(")")) {
            return null;
        }
        String value = term.substring(key.length(), term.length() - 1);
        for (int i = 0; i < value.length(); i++) {
            char c = value.charAt(i);
            if (c == '*' || c == '(' || c == ')' || c == '\\' || Character.isWhitespace(c)) {
                return null;
            }
        }
        return value;
    }
}
