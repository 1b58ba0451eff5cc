package org.tinysep.launcher;

import java.io.IOException;
import java.lang.reflect.Method;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Dictionary;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceListener;
import org.osgi.framework.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Ready means ready: the banner, systemd's {@code READY=1} and the first heartbeat wait until the
 * platform is what the banner claims, the bus radios listening with their configuration from {@code etc/}:
 * <ol>
 * <li>every {@code etc/*.cfg} is in ConfigAdmin (FileInstall read it: property {@code felix.fileinstall.filename}),
 * so no component is still to be reconfigured (a reconfiguration closes and reopens a radio's socket, losing the
 * frames sent meanwhile);</li>
 * <li>then every Declarative Services component configured by one of those files runs with it
 * ({@link ConfiguredComponents}: a component that activated with its defaults before its file came has been
 * re-activated; issue 29: this check replaced 300 ms of waiting for a quiet service registry, which stays as the way
 * when there is no SCR to ask).</li>
 * </ol>
 * Both waits are bounded; a file ConfigAdmin never takes (a broken cfg) delays the banner by {@link #CONFIG_WAIT}
 * at most and is named in a WARN line.
 */
final class Readiness {

    static final long QUIET_MILLIS = 300;
    static final Duration CONFIG_WAIT = Duration.ofSeconds(10);
    static final Duration QUIET_WAIT = Duration.ofSeconds(10);
    private static final String CM = "org.osgi.service.cm.ConfigurationAdmin";
    private static final String FILENAME = "felix.fileinstall.filename";
    private static final Logger LOG = LoggerFactory.getLogger(Readiness.class);

    private Readiness() {
    }

    static void await(BundleContext context, Path etc, StartTrace trace) throws InterruptedException {
        AtomicLong lastChange = new AtomicLong(System.nanoTime());
        String[] last = {"none"};
        ServiceListener listener = event -> {
            lastChange.set(System.nanoTime());
            last[0] = String.valueOf(event.getServiceReference().getProperty("component.name"));
        };
        context.addServiceListener(listener);
        try {
            Set<String> missing = cfgFiles(etc);
            long end = System.nanoTime() + CONFIG_WAIT.toNanos();
            while (true) {
                missing.removeAll(applied(context));
                if (missing.isEmpty() || System.nanoTime() > end) {
                    break;
                }
                Thread.sleep(20);
            }
            if (!missing.isEmpty()) {
                LOG.warn("ConfigAdmin has not taken {} from {} within {} s (a broken file?)", missing, etc,
                        CONFIG_WAIT.toSeconds());
            }
            trace.mark("every etc/*.cfg in ConfigAdmin");
            Set<String> files = cfgFiles(etc);
            long configuredEnd = System.nanoTime() + QUIET_WAIT.toNanos();
            Optional<List<ConfiguredComponents.Component>> components = ConfiguredComponents.read(context);
            Set<String> waiting = Set.of();
            while (components.isPresent() && System.nanoTime() < configuredEnd) {
                waiting = ConfiguredComponents.waitingFor(files, components.get());
                if (waiting.isEmpty()) {
                    trace.mark("every component configured by etc/ runs with its file");
                    return;
                }
                Thread.sleep(20);
                components = ConfiguredComponents.read(context);
            }
            if (components.isPresent()) {
                LOG.warn("Components configured by {} do not run with them after {} s", waiting, QUIET_WAIT.toSeconds());
                return;
            }
            // no Declarative Services to ask: the service registry quiet for a while instead
            long quietEnd = System.nanoTime() + QUIET_WAIT.toNanos();
            while (System.nanoTime() - lastChange.get() < QUIET_MILLIS * 1_000_000 && System.nanoTime() < quietEnd) {
                Thread.sleep(20);
            }
            trace.mark("service registry quiet for " + QUIET_MILLIS + " ms (last change: component " + last[0] + ")");
        } finally {
            context.removeServiceListener(listener);
        }
    }

    static Set<String> cfgFiles(Path etc) {
        Set<String> out = new HashSet<>();
        if (!Files.isDirectory(etc)) {
            return out;
        }
        try (DirectoryStream<Path> files = Files.newDirectoryStream(etc, "*.cfg")) {
            files.forEach(f -> out.add(f.getFileName().toString()));
        } catch (IOException e) {
            LOG.debug("Cannot list {}: {}", etc, e.toString());
        }
        return out;
    }

    /** @return the file names of the configurations FileInstall put into ConfigAdmin */
    private static Set<String> applied(BundleContext context) {
        Set<String> out = new HashSet<>();
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(CM, null);
            if (refs == null) {
                return out;
            }
            Object cm = context.getService(refs[0]);
            try {
                Class<?> type = refs[0].getBundle().loadClass(CM);
                Object[] configs = (Object[]) type.getMethod("listConfigurations", String.class)
                        .invoke(cm, "(" + FILENAME + "=*)");
                if (configs != null) {
                    Method props = refs[0].getBundle().loadClass("org.osgi.service.cm.Configuration")
                            .getMethod("getProperties");
                    for (Object c : configs) {
                        Object name = ((Dictionary<?, ?>) props.invoke(c)).get(FILENAME);
                        String s = String.valueOf(name);
                        out.add(s.substring(s.lastIndexOf('/') + 1));
                    }
                }
            } finally {
                context.ungetService(refs[0]);
            }
        } catch (Exception e) {
            LOG.debug("Cannot read ConfigAdmin's configurations: {}", e.toString());
        }
        return out;
    }
}
