package org.tinysep.itests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;
import static org.ops4j.pax.exam.CoreOptions.bundle;
import static org.ops4j.pax.exam.CoreOptions.cleanCaches;
import static org.ops4j.pax.exam.CoreOptions.frameworkProperty;
import static org.ops4j.pax.exam.CoreOptions.junitBundles;
import static org.ops4j.pax.exam.CoreOptions.mavenBundle;
import static org.ops4j.pax.exam.CoreOptions.systemProperty;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;
import javax.inject.Inject;
import org.apache.felix.service.command.CommandProcessor;
import org.apache.felix.service.command.CommandSession;
import org.apache.felix.service.command.Converter;
import org.ops4j.pax.exam.Configuration;
import org.ops4j.pax.exam.Option;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Filter;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;

/**
 * Base of every TinySEP integration test: a Felix framework (Pax Exam native container) provisioned like the
 * launcher's distribution, plus helpers to drive it.
 *
 * <p>Start levels mirror the launcher: 1 ASM + SPI Fly, then the SLF4J bundles (also level 1, installed after
 * SPI Fly: Pax Exam's own bundles take level 2 and must find a bound SLF4J), 3 system services, 4 platform
 * (API, drivers list, device manager), 5 applications (and Pax Exam's probe). Without {@code tinysep.home} the
 * drivers list starts empty in its bundle's data area: Pax Exam provisions the applications itself.
 *
 * <p>Like the distribution, FileInstall applies ConfigAdmin configurations from a folder before the platform
 * starts ({@link #initialConfigurations()}); {@link #configure(String, Map)} changes them while a test runs.
 *
 * <p>Third-party bundles come from Maven's local repository ({@code versionAsInProject()}); the reactor's own
 * bundles come from {@code file:} URLs in the system properties {@code bundle.<artifactId>} set by the pom.
 */
public abstract class TinySepTestSupport {

    /** ConfigAdmin pid of the UDP bus radio (keys {@code port}, {@code bindAddress}). */
    public static final String UDP_PID = "org.tinysep.amica.busradio.udp";
    /** ConfigAdmin pid of the Sun SPOT bus radio (keys {@code udpPort}, {@code udpBindAddress}, …). */
    public static final String SUN_SPOT_PID = "org.tinysep.sunspot.busradio";
    /** Driver name (and device type) of the AmICA UDP bus radio, whose port {@link #udpPortOf(String)} tells. */
    protected static final String BUS = "BusRadioAmicaUdp";
    /** Driver service property carrying the UDP bus radio's bound port. */
    public static final String UDP_PORT_PROPERTY = "tinysep.udp.port";
    /** The drivers of thesis Fig 3.3 (and the codec they share): the first vertical slice. */
    protected static final List<String> FIRST_SLICE = List.of("org.tinysep.amica.protocol",
            "org.tinysep.amica.busradio.udp", "org.tinysep.amica.movement", "org.tinysep.amica.door",
            "org.tinysep.flatoccupancy");
    /** The AmICA hardware bundles beyond the first slice; provisioned by default. */
    protected static final List<String> AMICA_HARDWARE = List.of("org.tinysep.amica.busradio.serial",
            "org.tinysep.amica.window", "org.tinysep.amica.simplelight", "org.tinysep.amica.dimmablelight",
            "org.tinysep.amica.heater", "org.tinysep.amica.speaker", "org.tinysep.amica.petmovement",
            "org.tinysep.amica.presence");
    /** The intermediate and AAL services beyond Flat Occupancy; provisioned by default. */
    protected static final List<String> SERVICES = List.of("org.tinysep.houseinformation",
            "org.tinysep.timecontroller", "org.tinysep.mailmanager", "org.tinysep.inactivity",
            "org.tinysep.followmelight");
    /**
     * The Sun SPOT bundles, in install order. Not provisioned by default: thesis scenario 3 installs them at
     * runtime; other tests add them with {@link #sunSpotBundles(int)}.
     */
    protected static final List<String> SUN_SPOT = List.of("org.tinysep.sunspot.protocol",
            "org.tinysep.sunspot.busradio", "org.tinysep.sunspot.movement", "org.tinysep.sunspot.temperature",
            "org.tinysep.sunspot.light", "org.tinysep.sunspot.petmovement");
    /**
     * Default time limit of the helpers: a bound for a loaded CI machine, not a speed assertion (a wait ends as soon
     * as its condition holds; 10 s was exceeded once on a busy CI run).
     */
    protected static final Duration TIMEOUT = Duration.ofSeconds(30);

    protected final Logger log = LoggerFactory.getLogger(getClass());

    @Inject
    protected BundleContext context;

    /** Pax Exam entry point; extend {@link #options()} rather than overriding this. */
    @Configuration
    public Option[] configuration() {
        return options().toArray(new Option[0]);
    }

    /**
     * The provisioning. Subclasses add bundles with {@code List<Option> o = super.options(); o.add(...); return o;}.
     *
     * @return a mutable list
     */
    protected List<Option> options() {
        List<Option> o = new ArrayList<>();
        o.add(cleanCaches(true));
        o.add(junitBundles());
        // the test class path holds slf4j-simple too: without this, Felix lets java.util.ServiceLoader see it
        // ("SimpleServiceProvider not a subtype") and SLF4J falls back to NOP inside the framework
        o.add(frameworkProperty("felix.bootdelegation.implicit").value("false"));
        // jSerialComm loads its JNI library once per class loader and the JVM refuses the same library file in a
        // second one: every framework after the first in this JVM (one per test class or method) would fail to
        // open any port ("Cannot load native library"). A random file name per load avoids that.
        o.add(systemProperty("jSerialComm.library.randomizeNativeName").value("true"));
        for (String key : List.of("org.ops4j.pax.url.mvn.localRepository", "org.ops4j.pax.url.mvn.repositories",
                "org.slf4j.simpleLogger.defaultLogLevel", "org.slf4j.simpleLogger.showDateTime", "org.slf4j.simpleLogger.dateTimeFormat",
                "org.slf4j.simpleLogger.showShortLogName")) {
            if (System.getProperty(key) != null) {
                o.add(systemProperty(key).value(System.getProperty(key)));
            }
        }
        // level 1: weaving for the Service Loader Mediator, then SLF4J (pitfall 1)
        for (String asm : List.of("asm", "asm-commons", "asm-util", "asm-tree", "asm-analysis")) {
            o.add(mavenBundle("org.ow2.asm", asm).versionAsInProject().startLevel(1));
        }
        o.add(mavenBundle("org.apache.aries.spifly", "org.apache.aries.spifly.dynamic.bundle").versionAsInProject().startLevel(1));
        o.add(mavenBundle("org.slf4j", "slf4j-api").versionAsInProject().startLevel(1));
        o.add(mavenBundle("org.slf4j", "slf4j-simple").versionAsInProject().startLevel(1));
        // level 3: system services
        o.add(mavenBundle("org.osgi", "org.osgi.util.function").versionAsInProject().startLevel(3));
        o.add(mavenBundle("org.osgi", "org.osgi.util.promise").versionAsInProject().startLevel(3));
        o.add(mavenBundle("org.osgi", "org.osgi.service.component").versionAsInProject().startLevel(3));
        o.add(mavenBundle("org.apache.felix", "org.apache.felix.scr").versionAsInProject().startLevel(3));
        o.add(mavenBundle("org.apache.felix", "org.apache.felix.configadmin").versionAsInProject().startLevel(3));
        o.addAll(fileInstall()); // after ConfigAdmin: applies initialConfigurations() before level 4 starts
        o.add(mavenBundle("org.apache.felix", "org.apache.felix.gogo.runtime").versionAsInProject().startLevel(3));
        o.add(mavenBundle("org.apache.felix", "org.apache.felix.gogo.command").versionAsInProject().startLevel(3));
        // level 4: platform
        o.add(reactorBundle("org.tinysep.api", 4));
        o.add(reactorBundle("org.tinysep.drivers", 4));
        o.add(reactorBundle("org.tinysep.runtime", 4));
        // test helpers the probe uses (SmtpSink, SocatPair, PtyPeer): exported by the test-support bundle
        o.add(reactorBundle("org.tinysep.testsupport.io", 4));
        // libraries some applications need
        o.add(mavenBundle("com.fazecast", "jSerialComm").versionAsInProject().startLevel(3));
        o.add(mavenBundle("jakarta.activation", "jakarta.activation-api").versionAsInProject().startLevel(3));
        o.add(mavenBundle("jakarta.xml.bind", "jakarta.xml.bind-api").versionAsInProject().startLevel(3));
        o.add(mavenBundle("com.sun.xml.bind", "jaxb-osgi").versionAsInProject().startLevel(3));
        // level 5: application bundles (system properties bundle.<artifactId>, see pom.xml)
        for (String application : applications()) {
            o.add(reactorBundle(application, 5));
        }
        // The bus radio starts on a free port (initialConfigurations()); tests send to udpPortOf("BusRadioAmicaUdp").
        return o;
    }

    /**
     * ConfigAdmin configurations that exist before any TinySEP bundle starts, as {@code pid → key → value}
     * (written as {@code <pid>.cfg} into a folder FileInstall watches, like the distribution's {@code etc/}).
     * The default puts the UDP bus radios (AmICA, and Sun SPOT once installed) on free ports of 127.0.0.1 ({@link #udpPortOf(String)} tells which),
     * so tests never bind the production port. Subclasses may add entries.
     */
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>();
        configs.put(UDP_PID, Map.of("port", "0", "bindAddress", "127.0.0.1"));
        // used only once Sun SPOT bundles are installed: their UDP link on a free port too
        configs.put(SUN_SPOT_PID, Map.of("udpPort", "0", "udpBindAddress", "127.0.0.1"));
        return configs;
    }

    /** FileInstall on {@code target/itest-etc/<test class>/}, filled from {@link #initialConfigurations()}. */
    /**
     * For {@link #initialConfigurations()} overrides: {@code configs} with the configuration of {@code pid}
     * replaced by {@code config}.
     */
    protected static Map<String, Map<String, String>> replacing(Map<String, Map<String, String>> configs, String pid,
            Map<String, String> config) {
        configs.put(pid, config);
        return configs;
    }

    private List<Option> fileInstall() {
        Path etc = Path.of("target", "itest-etc", getClass().getSimpleName()).toAbsolutePath();
        try {
            Files.createDirectories(etc);
            try (Stream<Path> old = Files.list(etc)) {
                for (Path file : old.toList()) {
                    Files.delete(file);
                }
            }
            for (Map.Entry<String, Map<String, String>> config : initialConfigurations().entrySet()) {
                StringBuilder text = new StringBuilder();
                config.getValue().forEach((key, value) -> text.append(key).append('=').append(value).append('\n'));
                Files.writeString(etc.resolve(config.getKey() + ".cfg"), text);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("Cannot prepare " + etc, e);
        }
        return List.of(
                frameworkProperty("felix.fileinstall.dir").value(etc.toString()),
                frameworkProperty("felix.fileinstall.filter").value(".*\\.cfg"),
                frameworkProperty("felix.fileinstall.noInitialDelay").value("true"),
                frameworkProperty("felix.fileinstall.poll").value("500"),
                frameworkProperty("felix.fileinstall.enableConfigSave").value("false"),
                frameworkProperty("felix.fileinstall.log.level").value("2"),
                mavenBundle("org.apache.felix", "org.apache.felix.fileinstall").versionAsInProject().startLevel(3));
    }

    /**
     * A bundle of this reactor, by the jar path the build put in system property {@code bundle.<artifactId>}.
     *
     * @throws IllegalStateException when the property is missing (not declared in the pom)
     */
    protected static Option reactorBundle(String artifactId, int startLevel) {
        String path = System.getProperty("bundle." + artifactId);
        if (path == null || path.isBlank() || path.startsWith("${")) {
            throw new IllegalStateException("System property bundle." + artifactId + " is not set: declare "
                    + artifactId + " as a test dependency and in surefire's systemPropertyVariables (itests/pom.xml)");
        }
        return bundle(new File(path).toURI().toString()).startLevel(startLevel);
    }

    /**
     * The application bundles installed at level 5. By default the first slice, every AmICA bundle and every
     * service; a test of a thesis scenario narrows it to the drivers the thesis loads.
     */
    protected List<String> applications() {
        List<String> all = new ArrayList<>(FIRST_SLICE);
        all.addAll(AMICA_HARDWARE);
        all.addAll(SERVICES);
        return all;
    }

    /** @return {@code base} (e.g. {@code super.applications()}) and then {@code more}, in a new list */
    protected static List<String> plus(List<String> base, String... more) {
        List<String> all = new ArrayList<>(base);
        all.addAll(List.of(more));
        return all;
    }

    /** @return provisioning options for every Sun SPOT bundle at {@code startLevel} */
    protected static List<Option> sunSpotBundles(int startLevel) {
        return SUN_SPOT.stream().map(b -> reactorBundle(b, startLevel)).toList();
    }

    /** @return the {@code file:} URL of a reactor bundle, for installing it at runtime (e.g. {@code install <url>}) */
    protected static String bundleUrl(String artifactId) {
        String path = System.getProperty("bundle." + artifactId);
        if (path == null || path.startsWith("${")) {
            throw new IllegalStateException("System property bundle." + artifactId + " is not set (itests/pom.xml)");
        }
        return new File(path).toURI().toString();
    }

    /**
     * Executes a Gogo command line, as typed in the shell.
     *
     * @return what the command printed plus its formatted result
     * @throws AssertionError when the command fails, with its output
     */
    protected String shell(String commandLine) {
        CommandProcessor processor = awaitService(CommandProcessor.class, null, TIMEOUT);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        try (CommandSession session = processor.createSession(new ByteArrayInputStream(new byte[0]), out, out)) {
            Object result = session.execute(commandLine);
            if (result != null) {
                out.println(session.format(result, Converter.INSPECT));
            }
        } catch (Exception e) {
            throw new AssertionError("'" + commandLine + "' failed: " + e + "\n" + bytes.toString(StandardCharsets.UTF_8), e);
        }
        String text = bytes.toString(StandardCharsets.UTF_8);
        log.info("g! {}\n{}", commandLine, text);
        return text;
    }

    /**
     * Waits until the device graph ({@link Topology#of(BundleContext)}) is exactly {@code expected}; on timeout fails
     * with an equality assertion, so the report shows the missing and extra lines.
     */
    protected void expectTopology(Set<String> expected) {
        Set<String> want = new TreeSet<>(expected);
        try {
            await(TIMEOUT, () -> Topology.of(context).equals(want), "device graph " + want);
        } catch (AssertionError timeout) {
            assertEquals("device graph", want, Topology.of(context)); // shows the difference
        }
    }

    /** @return a simulated AmICA node that talks to the running UDP bus radio ({@code BusRadioAmicaUdp}) */
    protected AmicaNode node(int netgroup, int address, AmicaNodeType... types) throws IOException {
        return new AmicaNode(netgroup, address, udpPortOf(BUS), types);
    }

    /**
     * A {@link #node(int, int, AmicaNodeType...)} that has sent its keep-alive, so the platform picks it up: the
     * usual first step of a test that needs the node's devices.
     */
    protected AmicaNode awakeNode(int netgroup, int address, AmicaNodeType... types) throws IOException {
        AmicaNode node = node(netgroup, address, types);
        try {
            node.keepAlive();
        } catch (IOException | RuntimeException e) {
            node.close();
            throw e;
        }
        return node;
    }

    /** @return the UDP port of the Time Controller's synchroniser (service property {@code tinysep.sync.port}) */
    protected int syncPort() {
        String filter = "(&(" + DeviceProperties.DRIVER_NAME + "=TimeController)(tinysep.sync.port=*))";
        awaitService(Driver.class, filter, TIMEOUT);
        try {
            return ((Number) context.getServiceReferences(Driver.class.getName(), filter)[0]
                    .getProperty("tinysep.sync.port")).intValue();
        } catch (Exception e) {
            throw new AssertionError("no TimeController driver with tinysep.sync.port", e);
        }
    }

    /**
     * Waits for a service and returns it.
     *
     * @param ldapFilter extra filter on service properties, or {@code null}
     * @throws AssertionError after {@code timeout}
     */
    protected <T> T awaitService(Class<T> type, String ldapFilter, Duration timeout) {
        ServiceReference<?> ref = awaitReference(type, ldapFilter, timeout);
        return type.cast(context.getService(ref));
    }

    /**
     * Polls {@code condition} every 20 ms until it holds.
     *
     * @param what what is awaited, for the failure message
     * @throws AssertionError after {@code timeout}
     */
    protected void await(Duration timeout, BooleanSupplier condition, String what) {
        await(timeout, condition, () -> what);
    }

    /** As {@link #await(Duration, BooleanSupplier, String)}; {@code what} is asked at the timeout (what was seen). */
    protected void await(Duration timeout, BooleanSupplier condition, java.util.function.Supplier<String> what) {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() - deadline > 0) {
                fail("Timed out after " + timeout.toMillis() + " ms waiting for " + what.get());
            }
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("Interrupted waiting for " + what.get());
            }
        }
    }

    /**
     * The UDP port a bus radio driver is bound to: its Driver service property {@value #UDP_PORT_PROPERTY}.
     *
     * @param driverName the driver's {@link DeviceProperties#DRIVER_NAME}
     */
    protected int udpPortOf(String driverName) {
        String filter = "(&(" + DeviceProperties.DRIVER_NAME + "=" + driverName + ")(" + UDP_PORT_PROPERTY + "=*))";
        Object port = awaitReference(Driver.class, filter, TIMEOUT).getProperty(UDP_PORT_PROPERTY);
        return port instanceof Number n ? n.intValue() : Integer.parseInt(port.toString().trim());
    }

    /** Creates or replaces the ConfigAdmin configuration {@code pid} (any location) with {@code props}. */
    protected void configure(String pid, Map<String, ?> props) {
        ConfigurationAdmin admin = awaitService(ConfigurationAdmin.class, null, TIMEOUT);
        try {
            admin.getConfiguration(pid, "?").update(new Hashtable<>(props));
        } catch (Exception e) {
            throw new AssertionError("Cannot configure " + pid + ": " + e, e);
        }
    }

    private ServiceReference<?> awaitReference(Class<?> type, String ldapFilter, Duration timeout) {
        String spec = "(&(objectClass=" + type.getName() + ")" + (ldapFilter == null ? "" : ldapFilter) + ")";
        Filter filter;
        try {
            filter = context.createFilter(spec);
        } catch (InvalidSyntaxException e) {
            throw new IllegalArgumentException("Bad filter " + spec, e);
        }
        ServiceTracker<?, ?> tracker = new ServiceTracker<>(context, filter, null);
        tracker.open(true);
        try {
            if (tracker.waitForService(timeout.toMillis()) == null) {
                fail("Timed out after " + timeout.toMillis() + " ms waiting for a service " + spec);
            }
            return tracker.getServiceReference();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("Interrupted waiting for " + spec, e);
        } finally {
            tracker.close();
        }
    }
}
