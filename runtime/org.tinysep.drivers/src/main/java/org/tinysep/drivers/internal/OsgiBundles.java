package org.tinysep.drivers.internal;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.FrameworkListener;
import org.osgi.framework.startlevel.BundleStartLevel;
import org.osgi.framework.startlevel.FrameworkStartLevel;
import org.osgi.framework.wiring.FrameworkWiring;

/** {@link Bundles} on a real framework. Remembers the last error the framework reported per bundle, for statuses. */
final class OsgiBundles implements Bundles, FrameworkListener {

    private final BundleContext context;
    private final Map<Long, String> errors = new ConcurrentHashMap<>();

    OsgiBundles(BundleContext context) {
        this.context = context;
    }

    @Override
    public long find(String symbolicName, String location) {
        Bundle byLocation = context.getBundle(location);
        if (byLocation != null) {
            return byLocation.getBundleId();
        }
        if (!symbolicName.isEmpty()) {
            for (Bundle b : context.getBundles()) {
                if (symbolicName.equals(b.getSymbolicName())) {
                    return b.getBundleId();
                }
            }
        }
        return -1;
    }

    @Override
    public long install(String location, int startLevel) throws BundleException {
        Bundle b = context.installBundle(location);
        b.adapt(BundleStartLevel.class).setStartLevel(startLevel);
        return b.getBundleId();
    }

    @Override
    public String symbolicName(long id) {
        Bundle b = context.getBundle(id);
        return b == null || b.getSymbolicName() == null ? "" : b.getSymbolicName();
    }

    @Override
    public void start(long id) throws BundleException {
        errors.remove(id);
        Bundle b = bundle(id);
        if (b.getHeaders().get("Fragment-Host") == null) {
            b.start();
        }
    }

    @Override
    public void stop(long id) throws BundleException {
        bundle(id).stop();
    }

    @Override
    public void uninstall(long id) throws BundleException, InterruptedException {
        Bundle b = bundle(id);
        b.uninstall();
        // only the removed bundle (and, through it, its dependents) is refreshed: never the whole framework
        CountDownLatch done = new CountDownLatch(1);
        context.getBundle(0).adapt(FrameworkWiring.class).refreshBundles(List.of(b), e -> done.countDown());
        done.await(30, TimeUnit.SECONDS);
    }

    @Override
    public boolean isRunning(long id) {
        Bundle b = context.getBundle(id);
        return b != null && (b.getState() == Bundle.ACTIVE || b.getState() == Bundle.STARTING);
    }

    @Override
    public String status(long id) {
        Bundle b = context.getBundle(id);
        if (b == null) {
            return "";
        }
        String error = errors.get(id);
        return switch (b.getState()) {
            case Bundle.ACTIVE -> Status.ACTIVE;
            case Bundle.STARTING -> Status.STARTING;
            case Bundle.RESOLVED -> error == null ? Status.STOPPED : Status.failed(error);
            case Bundle.INSTALLED -> waitingForStartLevel(b) ? Status.INSTALLED
                    : Status.failed(error == null ? "not resolved (see the log)" : error);
            default -> Status.STOPPED;
        };
    }

    private boolean waitingForStartLevel(Bundle b) {
        int framework = context.getBundle(0).adapt(FrameworkStartLevel.class).getStartLevel();
        return b.adapt(BundleStartLevel.class).getStartLevel() > framework;
    }

    @Override
    public void frameworkEvent(FrameworkEvent event) {
        if (event.getType() == FrameworkEvent.ERROR && event.getBundle() != null && event.getThrowable() != null) {
            errors.put(event.getBundle().getBundleId(), oneLine(event.getThrowable()));
        }
    }

    private Bundle bundle(long id) throws BundleException {
        Bundle b = context.getBundle(id);
        if (b == null) {
            throw new BundleException("bundle " + id + " is gone");
        }
        return b;
    }

    private static String oneLine(Throwable t) {
        Throwable root = t;
        while (root.getCause() != null && root.getCause() != root) {
            root = root.getCause();
        }
        String msg = root.getMessage() == null ? root.toString() : root.getMessage();
        return msg.replaceAll("\\s+", " ").strip();
    }
}
