package org.tinysep.drivers.internal;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.FrameworkListener;
import org.osgi.framework.SynchronousBundleListener;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Nothing switches a watching application off in silence: whatever stops, removes or replaces
 * one ({@link WatchingApp}) — the drivers list, the web console, the shell's {@code stop}/{@code update}, an
 * upload — is a {@code PROBLEM} entry starting {@code Monitoring reduced: }, which the alert service's notices
 * mail to the caregivers. While the platform shuts down nothing is reported. A stop is reported after
 * {@value #GRACE_SECONDS} s if the application has not come back (an update or refresh restarts it at once). When
 * the alert service itself goes, nothing is left to mail its notice: this component sends it through the Mail
 * Manager directly.
 */
@Component(service = {}, immediate = true)
public final class WatchGuard implements SynchronousBundleListener, FrameworkListener {

    static final int GRACE_SECONDS = 10; // longer than a restore, which stops and starts the applications
    private static final Logger LOG = LoggerFactory.getLogger(WatchGuard.class);

    private final BundleContext context;
    private final EventLog events;
    private final DriversList list;
    private final Map<Long, String[]> known = new ConcurrentHashMap<>(); // id -> version, location
    private final ScheduledExecutorService executor = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "tinysep-watch-guard");
        t.setDaemon(true);
        return t;
    });
    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile MailManagerProvider mail;

    @Activate
    public WatchGuard(BundleContext context, @Reference(name = "eventLog") EventLog events,
            @Reference(name = "list") DriversList list) {
        this.context = context;
        this.events = events;
        this.list = list;
        for (Bundle b : context.getBundles()) {
            remember(b);
        }
        context.addBundleListener(this);
        context.addFrameworkListener(this);
        if (context.getBundle(0).getState() == Bundle.ACTIVE) {
            disabledAtStart(); // this bundle restarted on a running platform
        }
    }

    @Deactivate
    void deactivate() {
        context.removeBundleListener(this);
        context.removeFrameworkListener(this);
        executor.shutdownNow();
    }

    @Override
    public void frameworkEvent(FrameworkEvent event) {
        if (event.getType() == FrameworkEvent.STARTED) {
            disabledAtStart();
        }
    }

    @Override
    public void bundleChanged(BundleEvent event) {
        Bundle b = event.getBundle();
        Optional<WatchingApp> app = WatchingApp.of(b.getSymbolicName());
        if (app.isEmpty()) {
            return;
        }
        if (shuttingDown()) {
            return; // the platform stops: not a reduction anybody caused
        }
        String[] before = known.get(b.getBundleId());
        switch (event.getType()) {
            case BundleEvent.STOPPED -> executor.schedule(() -> stillStopped(b, app.get()), GRACE_SECONDS,
                    TimeUnit.SECONDS);
            case BundleEvent.UNINSTALLED -> reduced(app.get(), app.get().removed(version(b)));
            case BundleEvent.UPDATED -> reduced(app.get(), app.get().replaced(before == null ? "?" : before[0],
                    before == null ? "?" : before[1], version(b), b.getLocation()));
            default -> {
            }
        }
        remember(b);
    }

    private void stillStopped(Bundle b, WatchingApp app) {
        int s = b.getState();
        if (!shuttingDown() && s != Bundle.ACTIVE && s != Bundle.STARTING && s != Bundle.UNINSTALLED) {
            reduced(app, app.stopped(version(b)));
        }
    }

    /** At the end of the start: a watching application disabled in the drivers list is said again. */
    private void disabledAtStart() {
        for (DriverEntry e : list.entries()) {
            WatchingApp.of(e.symbolicName()).filter(a -> !e.enabled())
                    .ifPresent(a -> reduced(a, a.disabledAtStart()));
        }
    }

    private void reduced(WatchingApp app, String message) {
        LOG.warn("{}", message);
        events.record(EventKind.PROBLEM, Report.ORIGIN, message);
        MailManagerProvider m = mail;
        if (app == WatchingApp.ALERTS && m != null) { // its notices went with it
            try {
                m.send("TinySEP watches less than it should: the alert service was stopped or replaced",
                        message + "\n\nWhat this means: until this is put right, TinySEP may not notice when the "
                        + "person needs help, and alerts are not repeated or passed on.\nWhat to do: if you did not "
                        + "expect this, ask the person who installed TinySEP to check it today.\n");
                events.record(EventKind.DEVICE_EVENT, Report.ORIGIN, "notice sent to the caregivers by the "
                        + "drivers list (the alert service, which sends notices, is not running)");
            } catch (RuntimeException ex) {
                LOG.warn("Could not queue the notice that the alert service stopped: {}", ex.toString());
            }
        }
    }

    private boolean shuttingDown() {
        int s = context.getBundle(0).getState();
        return s == Bundle.STOPPING || s == Bundle.RESOLVED;
    }

    private void remember(Bundle b) {
        if (b.getState() == Bundle.UNINSTALLED) {
            known.remove(b.getBundleId());
        } else {
            known.put(b.getBundleId(), new String[] {version(b), b.getLocation()});
        }
    }

    private static String version(Bundle b) {
        return b.getVersion() == null ? "?" : b.getVersion().toString();
    }
}
