package org.tinysep.launcher;

import java.lang.reflect.Method;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.launch.Framework;

/**
 * Is the platform really alive? Not a timer: each check goes through the framework and Declarative Services into
 * the platform — the framework is ACTIVE, SCR answers for its components ({@code ServiceComponentRuntime}) and the
 * event log answers ({@code EventLog.recent(1)}). A deadlock in SCR, the event log or the framework's registry makes
 * the check hang; a stopped framework or a missing service makes it fail. The classes live in bundles the launcher
 * cannot see, so the calls are reflective.
 */
final class LivenessProbe implements Heartbeat.Probe {

    static final String SCR = "org.osgi.service.component.runtime.ServiceComponentRuntime";
    static final String EVENT_LOG = "org.tinysep.api.log.EventLog";

    private final Framework framework;

    LivenessProbe(Framework framework) {
        this.framework = framework;
    }

    /** @throws IllegalStateException saying in plain words what does not answer */
    @Override
    public void check() throws Exception {
        if ((framework.getState() & (Bundle.STOPPING | Bundle.RESOLVED)) != 0) {
            throw new Stopping();
        }
        if (framework.getState() != Bundle.ACTIVE) {
            throw new IllegalStateException("the OSGi framework is not active (state " + framework.getState() + ")");
        }
        BundleContext context = framework.getBundleContext();
        call(context, SCR, "Declarative Services (SCR)", "getComponentDescriptionDTOs", new Class<?>[] {Bundle[].class},
                (Object) new Bundle[0]);
        call(context, EVENT_LOG, "the event log", "recent", new Class<?>[] {int.class}, 1);
    }

    @Override
    public boolean stopping() {
        return (framework.getState() & (Bundle.STOPPING | Bundle.RESOLVED)) != 0;
    }

    /** The framework is stopping (a clean stop): no heartbeat, and nothing to warn about. */
    static final class Stopping extends IllegalStateException {
        private static final long serialVersionUID = 1L;

        Stopping() {
            super("TinySEP is stopping");
        }
    }

    private static void call(BundleContext context, String type, String what, String method, Class<?>[] types,
            Object... args) throws Exception {
        ServiceReference<?> ref = reference(context, type);
        if (ref == null) {
            throw new IllegalStateException(what + " is not running");
        }
        Object service = context.getService(ref);
        if (service == null) {
            throw new IllegalStateException(what + " cannot be obtained");
        }
        try {
            Method m = ref.getBundle() == null ? null : findMethod(service, type, method, types);
            if (m == null) {
                throw new IllegalStateException(what + " has no method " + method);
            }
            m.invoke(service, args);
        } finally {
            context.ungetService(ref);
        }
    }

    /** The interface's method, loaded through the service's own class space. */
    private static Method findMethod(Object service, String type, String method, Class<?>[] types) throws Exception {
        for (Class<?> c = service.getClass(); c != null; c = c.getSuperclass()) {
            for (Class<?> i : c.getInterfaces()) {
                if (i.getName().equals(type)) {
                    return i.getMethod(method, types);
                }
            }
        }
        return null;
    }

    private static ServiceReference<?> reference(BundleContext context, String type) throws InvalidSyntaxException {
        // all class spaces: the system bundle cannot see these interfaces
        ServiceReference<?>[] refs = context.getAllServiceReferences(type, null);
        return refs == null || refs.length == 0 ? null : refs[0];
    }
}
