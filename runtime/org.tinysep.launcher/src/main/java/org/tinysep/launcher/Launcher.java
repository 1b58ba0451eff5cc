package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarFile;
import java.util.jar.Manifest;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.framework.Constants;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.launch.Framework;
import org.osgi.framework.launch.FrameworkFactory;
import org.osgi.framework.startlevel.BundleStartLevel;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Embeds an OSGi framework (found through {@link FrameworkFactory} and {@link ServiceLoader}), installs the
 * distribution's bundle groups at their start levels and starts them. The Gogo shell bundle is installed only
 * in interactive mode and started last, by {@link #startShell()}, after the banner.
 */
public final class Launcher {

    /** Symbolic name of the interactive Gogo shell. */
    public static final String SHELL_BSN = "org.apache.felix.gogo.shell";
    /** Symbolic name of the drivers list bundle, which installs the {@value #APPS_GROUP} group when present. */
    public static final String DRIVERS_BSN = "org.tinysep.drivers";
    /** Name of the group the drivers list installs (folder {@code 5-apps}). */
    public static final String APPS_GROUP = "apps";
    /**
     * Name of the web console's group (folder {@code 4-web}: Felix HTTP on Jetty, the console's bundles): installed
     * and started on the console's first use ({@link #startWeb()}, {@link WebConsole}), so the HTTP service is
     * neither on the start path nor in the idle platform's memory; never on a headless gateway
     * ({@link Options#headless()}).
     */
    public static final String WEB_GROUP = "web";

    private static final Logger LOG = LoggerFactory.getLogger(Launcher.class);
    private static final Duration START_TIMEOUT = Duration.ofSeconds(60);

    private final Options options;
    private final Map<Long, String> errors = new ConcurrentHashMap<>();
    private final Map<Bundle, String> groupOf = new LinkedHashMap<>();
    private final List<StartReport.Failure> installFailures = new ArrayList<>();
    /** Groups left to the drivers list: their bundles are reported, not installed, by the launcher. */
    private final List<BundleGroup> delegated = new ArrayList<>();
    /** The web console's group: installed and started on the console's first use ({@link #startWeb()}). */
    private BundleGroup webGroup;
    private volatile Framework framework;
    private Bundle shell;
    /** Closed when the framework stops (e.g. the web console's port held until its first use). */
    private final List<AutoCloseable> closeOnStop = new CopyOnWriteArrayList<>();

    public Launcher(Options options) {
        this.options = options;
    }

    /**
     * Creates, initialises and starts the framework and waits until it reaches its start level.
     *
     * @return the report for the banner
     * @throws IOException     when {@code bundles/} cannot be read
     * @throws BundleException when the framework itself cannot start
     */
    public StartReport start() throws IOException, BundleException, InterruptedException {
        long t0 = System.nanoTime();
        StartTrace trace = new StartTrace(t0);
        Path home = options.home();
        List<BundleGroup> groups = BundleLayout.scan(home.resolve("bundles"));
        int level = BundleLayout.maxStartLevel(groups);
        Files.createDirectories(home.resolve("deploy"));
        Files.createDirectories(home.resolve("etc"));
        PrivateFolder.tighten(options.var()).ifPresent(LOG::warn); // state folder rwx------ (docs/backup.md)
        LOG.info("Starting TinySEP from {}, state in {} ({} bundle groups, {})", home, options.var(), groups.size(),
                options.daemon() ? "daemon" : "interactive");

        Map<String, Object> config = new HashMap<>(FrameworkConfig.properties(home, options.var(), options.daemon(), level));
        config.put(FrameworkConfig.FELIX_LOGGER, new FelixLog()); // Felix takes a Logger instance here
        @SuppressWarnings({"unchecked", "rawtypes"})
        Map<String, String> launchProperties = (Map) config;
        Framework fw = ServiceLoader.load(FrameworkFactory.class).findFirst()
                .orElseThrow(() -> new IllegalStateException("no OSGi framework on the class path"))
                .newFramework(launchProperties);
        fw.init();
        framework = fw;
        trace.mark("framework initialised");
        trace.watch(fw.getBundleContext());
        // before anything of this start is logged: the history's end as the files on disk tell it
        StartSignals signals = new StartSignals(fw.getBundleContext(), EventHistoryEnd.read(home.resolve("etc"),
                options.var()));

        CountDownLatch started = new CountDownLatch(1);
        fw.getBundleContext().addFrameworkListener(event -> {
            if (event.getType() == FrameworkEvent.ERROR && event.getBundle() != null && event.getThrowable() != null) {
                errors.put(event.getBundle().getBundleId(), Failures.describe(event.getThrowable()));
            } else if (event.getType() == FrameworkEvent.STARTED) {
                started.countDown();
            }
        });
        boolean driversList = groups.stream().flatMap(g -> g.jars().stream())
                .anyMatch(jar -> DRIVERS_BSN.equals(symbolicName(jar)));
        for (BundleGroup group : groups) {
            if (driversList && APPS_GROUP.equals(group.name())) {
                delegated.add(group); // the drivers list (var/drivers.xml) installs and starts these
            } else if (WEB_GROUP.equals(group.name()) && options.headless()) {
                LOG.info("Headless gateway: not installing bundles/{} (the web console and its HTTP service)",
                        group.label());
            } else if (WEB_GROUP.equals(group.name())) {
                webGroup = group; // installed and started on the console's first use: startWeb()
            } else {
                install(fw.getBundleContext(), group);
            }
        }
        if (!driversList) {
            LOG.warn("No {} bundle: the launcher installs bundles/*-{} itself", DRIVERS_BSN, APPS_GROUP);
        }
        trace.mark("bundles installed");
        fw.start();
        if (!started.await(START_TIMEOUT.toSeconds(), TimeUnit.SECONDS)) {
            LOG.warn("Framework did not report STARTED within {} s", START_TIMEOUT.toSeconds());
        }
        Readiness.await(fw.getBundleContext(), home.resolve("etc"), trace); // the radios listen as configured
        StartReport report = report(Duration.ofNanos(System.nanoTime() - t0), level);
        trace.mark("banner");
        trace.log();
        return report.withWarnings(signals.warnings());
    }

    /**
     * Installs and starts the web console's group (on its first use: its HTTP service is not on the start path).
     * Does nothing on a headless gateway or without a {@code *-web} group.
     *
     * @return the bundles that did not start, each with a one-line reason (empty when all started)
     */
    public synchronized List<StartReport.Failure> startWeb() {
        List<StartReport.Failure> failures = new ArrayList<>();
        if (webGroup == null || framework == null) {
            return failures;
        }
        BundleContext context = framework.getBundleContext();
        List<Bundle> web = new ArrayList<>();
        for (Path jar : webGroup.jars()) {
            try {
                Bundle bundle = context.installBundle(jar.toUri().toString());
                bundle.adapt(BundleStartLevel.class).setStartLevel(webGroup.startLevel());
                web.add(bundle);
            } catch (BundleException | RuntimeException e) {
                failures.add(new StartReport.Failure(jar.getFileName().toString(), webGroup.label(),
                        "cannot install: " + Failures.describe(e)));
            }
        }
        for (Bundle b : web) {
            try {
                if (!isFragment(b)) {
                    b.start();
                }
            } catch (BundleException | RuntimeException e) {
                failures.add(new StartReport.Failure(b.getSymbolicName() + " " + b.getVersion(), webGroup.label(),
                        Failures.describe(e)));
            }
        }
        return failures;
    }

    /** @return whether this start has a web console (a {@code *-web} group, not headless) */
    public boolean hasWeb() {
        return webGroup != null;
    }

    /**
     * @param wait how long to wait for the Mail Manager to come up
     * @return the banner's line on where alerts go ({@code WARNING: …} when they reach nobody)
     */
    public String alertsLine(Duration wait) throws InterruptedException {
        return AlertRoute.line(framework.getBundleContext(), wait);
    }

    /** Starts the interactive Gogo shell, when it was installed (interactive mode). */
    public void startShell() throws BundleException {
        if (shell != null) {
            shell.start();
        }
    }

    /** @return the options this launcher starts with */
    public Options options() {
        return options;
    }

    /** @return the running framework, or {@code null} before {@link #start()} */
    public Framework framework() {
        return framework;
    }

    /**
     * Blocks until the framework has stopped.
     *
     * @return the process exit code: 0 after a normal stop, 1 after an error
     */
    public int awaitStop() throws InterruptedException {
        FrameworkEvent event = framework.waitForStop(0);
        return event.getType() == FrameworkEvent.ERROR ? 1 : 0;
    }

    /** Closes {@code resource} when the framework stops ({@link #stop(Duration)}). */
    void closeOnStop(AutoCloseable resource) {
        closeOnStop.add(resource);
    }

    /** Stops the framework, if running, and waits up to {@code timeout}. Safe to call more than once. */
    public void stop(Duration timeout) {
        closeOnStop.forEach(Launcher::closeQuietly);
        closeOnStop.clear();
        Framework fw = framework;
        if (fw == null || (fw.getState() & (Bundle.ACTIVE | Bundle.STARTING)) == 0) {
            return;
        }
        try {
            LOG.info("Stopping TinySEP");
            fw.stop();
            if (fw.waitForStop(timeout.toMillis()).getType() == FrameworkEvent.WAIT_TIMEDOUT) {
                LOG.warn("Framework did not stop within {} s", timeout.toSeconds());
            }
        } catch (BundleException e) {
            LOG.error("Could not stop the framework: {}", Failures.describe(e));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void closeQuietly(AutoCloseable resource) {
        try {
            resource.close();
        } catch (Exception e) {
            LOG.debug("Cannot close {}: {}", resource, e.toString());
        }
    }

    private void install(BundleContext context, BundleGroup group) {
        for (Path jar : group.jars()) {
            boolean isShell = SHELL_BSN.equals(symbolicName(jar));
            if (isShell && options.daemon()) {
                LOG.debug("Daemon mode: not installing {}", jar.getFileName());
                continue;
            }
            try {
                Bundle bundle = context.installBundle(jar.toUri().toString());
                bundle.adapt(BundleStartLevel.class).setStartLevel(group.startLevel());
                groupOf.put(bundle, group.label());
                if (isShell) {
                    shell = bundle;
                } else if (!isFragment(bundle)) {
                    bundle.start(); // marks it for starting when the framework reaches the group's level
                }
            } catch (BundleException | RuntimeException e) {
                installFailures.add(new StartReport.Failure(jar.getFileName().toString(), group.label(),
                        "cannot install: " + Failures.describe(e)));
            }
        }
    }

    /** Adds the bundles the drivers list installed from a delegated group's folder to {@code groupOf}. */
    private void collectDelegated() {
        for (BundleGroup group : delegated) {
            String folder = options.home().resolve("bundles").resolve(group.label()).toUri().toString();
            for (Bundle b : framework.getBundleContext().getBundles()) {
                String location = b.getLocation().replace("file:///", "file:/");
                if (!groupOf.containsKey(b) && location.startsWith(folder.replace("file:///", "file:/"))) {
                    groupOf.put(b, group.label());
                }
            }
        }
    }

    private StartReport report(Duration took, int level) {
        collectDelegated();
        Map<String, Integer> active = new LinkedHashMap<>();
        List<StartReport.Failure> failures = new ArrayList<>(installFailures);
        groupOf.forEach((bundle, group) -> {
            active.putIfAbsent(group, 0);
            if (bundle == shell) {
                return;
            }
            if (isUp(bundle)) {
                active.merge(group, 1, Integer::sum);
            } else {
                String reason = errors.getOrDefault(bundle.getBundleId(), "state " + stateName(bundle.getState()));
                failures.add(new StartReport.Failure(bundle.getSymbolicName() + " " + bundle.getVersion(), group, reason));
            }
        });
        delegated.forEach(g -> active.putIfAbsent(g.label(), 0));
        int installed = groupOf.size() - (shell == null ? 0 : 1) + installFailures.size();
        String version = Main.class.getPackage().getImplementationVersion();
        return new StartReport(version == null ? "(dev)" : version, took, level, options.daemon(),
                active, installed, failures);
    }

    private static boolean isUp(Bundle bundle) {
        return bundle.getState() == Bundle.ACTIVE
                || (isFragment(bundle) && bundle.getState() == Bundle.RESOLVED)
                || (bundle.getState() == Bundle.STARTING && "lazy".equals(bundle.getHeaders().get(Constants.BUNDLE_ACTIVATIONPOLICY)));
    }

    private static boolean isFragment(Bundle bundle) {
        return bundle.getHeaders().get(Constants.FRAGMENT_HOST) != null;
    }

    /** @return the jar's Bundle-SymbolicName without directives, or {@code null} */
    static String symbolicName(Path jar) {
        try (JarFile file = new JarFile(jar.toFile())) {
            Manifest manifest = file.getManifest();
            String bsn = manifest == null ? null : manifest.getMainAttributes().getValue(Constants.BUNDLE_SYMBOLICNAME);
            return bsn == null ? null : bsn.split(";")[0].trim();
        } catch (IOException e) {
            return null;
        }
    }

    static String stateName(int state) {
        return switch (state) {
            case Bundle.INSTALLED -> "INSTALLED (not resolved)";
            case Bundle.RESOLVED -> "RESOLVED (not started)";
            case Bundle.STARTING -> "STARTING";
            case Bundle.STOPPING -> "STOPPING";
            case Bundle.ACTIVE -> "ACTIVE";
            default -> "UNINSTALLED";
        };
    }
}
