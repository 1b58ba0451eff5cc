package org.tinysep.launcher;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.net.InetSocketAddress;
import java.util.Arrays;
import java.util.Hashtable;
import java.util.concurrent.atomic.AtomicLong;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceListener;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The web console started on first use (issue 29): {@link WebOnDemand} holds its port; the first connection, or the
 * shell's {@code tinysep:web-password} (a stand-in until the console's own command exists), starts
 * {@code bundles/4-web} ({@link Launcher#startWeb()}) and waits until Jetty serves with its final configuration.
 */
final class WebConsole {

    static final String PASSWORD_FILTER = "(&(osgi.command.scope=tinysep)(osgi.command.function=web-password))";
    private static final String FUNCTION = "org.apache.felix.service.command.Function";
    /** Felix HTTP restarts Jetty once when its configuration arrives: the console serves once its services are quiet. */
    private static final long QUIET_MILLIS = 200;
    private static final Logger LOG = LoggerFactory.getLogger(WebConsole.class);

    private final Launcher launcher;
    private ServiceRegistration<?> standIn;
    private WebOnDemand onDemand;

    private WebConsole(Launcher launcher) {
        this.launcher = launcher;
    }

    /** @return the console's address: the framework's properties, from {@code etc/org.apache.felix.http.cfg} */
    static InetSocketAddress address(BundleContext context) {
        return new InetSocketAddress(context.getProperty(HttpCfg.HOST), Integer.parseInt(context.getProperty(HttpCfg.PORT)));
    }

    /**
     * Holds the console's port until its first use.
     *
     * @throws IOException when the port cannot be bound (another program holds it)
     */
    static WebConsole onFirstUse(Launcher launcher, InetSocketAddress at) throws IOException {
        WebConsole console = new WebConsole(launcher);
        console.onDemand = WebOnDemand.listen(at, console::start);
        console.standIn = console.registerStandIn();
        launcher.closeOnStop(console.onDemand);
        return console;
    }

    private boolean start() throws InterruptedException {
        unregisterStandIn(); // the console's own tinysep:web-password comes with it
        long t0 = System.nanoTime();
        launcher.startWeb().forEach(f -> LOG.warn("The web console's bundle {} did not start: {}", f.bundle(), f.reason()));
        BundleContext context = launcher.framework().getBundleContext();
        AtomicLong lastChange = new AtomicLong(System.nanoTime());
        ServiceListener listener = event -> lastChange.set(System.nanoTime());
        context.addServiceListener(listener);
        try {
            String endpoint = WebConsoleLine.await(context, WebConsoleLine.WAIT);
            while (endpoint != null && System.nanoTime() - lastChange.get() < QUIET_MILLIS * 1_000_000L) {
                Thread.sleep(20);
            }
            LOG.info("Web console started on first use: {} ({} ms)", endpoint == null ? "did not bind" : endpoint,
                    (System.nanoTime() - t0) / 1_000_000);
            return endpoint != null;
        } finally {
            try {
                context.removeServiceListener(listener);
            } catch (IllegalStateException stopped) {
                // the framework stopped meanwhile
            }
        }
    }

    /** Until the console starts, {@code tinysep:web-password} in the shell starts it and hands the command over. */
    private ServiceRegistration<?> registerStandIn() {
        BundleContext context = launcher.framework().getBundleContext();
        Class<?> function = Arrays.stream(context.getBundles()).filter(b -> "org.apache.felix.gogo.runtime"
                .equals(b.getSymbolicName())).findFirst().map(WebConsole::functionType).orElse(null);
        if (function == null) {
            return null;
        }
        Object proxy = Proxy.newProxyInstance(function.getClassLoader(), new Class<?>[] {function},
                (self, method, args) -> switch (method.getName()) {
                    case "execute" -> passwordCommand(method, args);
                    case "hashCode" -> System.identityHashCode(self);
                    case "equals" -> self == args[0];
                    default -> "tinysep:web-password (starts the web console)";
                });
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("osgi.command.scope", "tinysep");
        props.put("osgi.command.function", "web-password");
        return context.registerService(FUNCTION, proxy, props);
    }

    private Object passwordCommand(Method execute, Object[] args) throws Exception {
        if (!onDemand.startNow()) {
            throw new IllegalStateException("the web console did not start (the log says why)");
        }
        BundleContext context = launcher.framework().getBundleContext();
        ServiceReference<?>[] refs = context.getAllServiceReferences(FUNCTION, PASSWORD_FILTER);
        long end = System.nanoTime() + WebConsoleLine.WAIT.toNanos();
        while (refs == null && System.nanoTime() < end) { // the console's components activate after it binds
            Thread.sleep(20);
            refs = context.getAllServiceReferences(FUNCTION, PASSWORD_FILTER);
        }
        if (refs == null) {
            throw new IllegalStateException("the web console started without its tinysep:web-password command");
        }
        Object command = context.getService(refs[0]);
        try {
            return execute.invoke(command, args);
        } catch (InvocationTargetException e) {
            throw e.getCause() instanceof Exception cause ? cause : e;
        } finally {
            context.ungetService(refs[0]);
        }
    }

    private synchronized void unregisterStandIn() {
        if (standIn != null) {
            try {
                standIn.unregister();
            } catch (IllegalStateException gone) {
                // the framework stops
            }
            standIn = null;
        }
    }

    private static Class<?> functionType(Bundle gogo) {
        try {
            return gogo.loadClass(FUNCTION);
        } catch (ClassNotFoundException e) {
            return null;
        }
    }
}
