package org.tinysep.web.api.internal;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.FrameworkListener;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;

/**
 * A console that cannot listen is not silent: when the framework has started and the HTTP
 * service has not come up within {@value #WAIT_SECONDS} s (Jetty did not start, e.g. its address is taken by
 * another program, which may then serve its own login page), a {@code PROBLEM} entry "Monitoring reduced: the web
 * console cannot listen on …" is written: a caregiver notice and a WARNING under the launcher's banner.
 */
@Component(immediate = true, service = {})
public final class ConsoleWatch implements FrameworkListener {

    static final int WAIT_SECONDS = 5;
    private static final String RUNTIME = "org.osgi.service.servlet.runtime.HttpServiceRuntime";
    private static final Logger LOG = LoggerFactory.getLogger(ConsoleWatch.class);

    private final BundleContext context;
    private final EventLog events;
    private final ScheduledExecutorService executor = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "tinysep-console-watch");
        t.setDaemon(true);
        return t;
    });

    @Activate
    public ConsoleWatch(BundleContext context, @Reference EventLog events) {
        this.context = context;
        this.events = events;
        context.addFrameworkListener(this);
        if (context.getBundle(0).getState() == Bundle.ACTIVE) {
            schedule();
        }
    }

    @Deactivate
    void deactivate() {
        context.removeFrameworkListener(this);
        executor.shutdownNow();
    }

    @Override
    public void frameworkEvent(FrameworkEvent event) {
        if (event.getType() == FrameworkEvent.STARTED) {
            schedule();
        }
    }

    private void schedule() {
        executor.schedule(this::check, WAIT_SECONDS, TimeUnit.SECONDS);
    }

    private void check() {
        if (runtimeUp() || context.getBundle(0).getState() != Bundle.ACTIVE) {
            return;
        }
        String message = message(context.getProperty("org.apache.felix.http.host"),
                context.getProperty("org.osgi.service.http.port"));
        LOG.error("{}", message);
        events.record(EventKind.PROBLEM, "web console", message);
    }

    static String message(String host, String port) {
        String where = (host == null || host.isBlank() ? "0.0.0.0" : host.strip()) + ":"
                + (port == null || port.isBlank() ? "8080" : port.strip());
        return "Monitoring reduced: the web console cannot listen on " + where + " (its HTTP service did not start "
                + "within " + WAIT_SECONDS + " s; the address is probably in use by another program, see the log): "
                + "caregivers cannot see or acknowledge alerts in the browser. A page that answers on that address "
                + "is NOT TinySEP's: do not enter a password there. Stop the other program, or set another port in "
                + "etc/org.apache.felix.http.cfg, then restart TinySEP";
    }

    private boolean runtimeUp() {
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(RUNTIME, null);
            return refs != null && refs.length > 0;
        } catch (InvalidSyntaxException | IllegalStateException e) {
            return true; // stopping: nothing to say
        }
    }
}
