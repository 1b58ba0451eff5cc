package org.tinysep.launcher;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.FrameworkListener;
import org.osgi.framework.SynchronousBundleListener;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where the start's time goes, at DEBUG ({@code -Dorg.slf4j.simpleLogger.log.org.tinysep.launcher.StartTrace=debug}):
 * the launcher's phases (framework created, bundles installed, start level reached, configurations applied, registry
 * quiet) and each bundle's {@code STARTING} and {@code STARTED} event, in ms since the launch, logged as one block
 * after the banner. Between a bundle's {@code STARTING} and {@code STARTED} runs its activator; after its
 * {@code STARTED}, Declarative Services activates its immediate components; before the next {@code STARTING}, the
 * next bundle is resolved.
 * Off (no listener) unless DEBUG is on for this logger. docs/footprint.md uses it.
 */
final class StartTrace {

    private static final Logger LOG = LoggerFactory.getLogger(StartTrace.class);

    private final long t0;
    private final List<String> lines = new ArrayList<>();
    private final boolean on = LOG.isDebugEnabled();

    /** @param t0 {@link System#nanoTime()} at the launch */
    StartTrace(long t0) {
        this.t0 = t0;
    }

    /** Listens to the framework's bundle and framework events (when DEBUG is on). */
    void watch(BundleContext context) {
        if (!on) {
            return;
        }
        context.addBundleListener((SynchronousBundleListener) e -> {
            if (e.getType() == BundleEvent.STARTING) {
                add("starting " + e.getBundle().getSymbolicName());
            } else if (e.getType() == BundleEvent.STARTED) {
                add("started  " + e.getBundle().getSymbolicName());
            }
        });
        context.addFrameworkListener((FrameworkListener) e -> {
            if (e.getType() == FrameworkEvent.STARTED || e.getType() == FrameworkEvent.STARTLEVEL_CHANGED) {
                add("framework start level reached");
            }
        });
    }

    /** Notes a phase of the launcher. */
    void mark(String phase) {
        if (on) {
            add(phase);
        }
    }

    private synchronized void add(String what) {
        lines.add(String.format(Locale.ROOT, "%7.0f ms  %s", (System.nanoTime() - t0) / 1e6, what));
    }

    /** Logs the timeline (DEBUG). */
    synchronized void log() {
        if (on) {
            LOG.debug("Start timeline (ms since the launch):\n{}", String.join("\n", lines));
        }
    }
}
