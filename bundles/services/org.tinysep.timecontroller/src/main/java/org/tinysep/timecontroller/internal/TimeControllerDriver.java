package org.tinysep.timecontroller.internal;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.ClockMode;
import org.tinysep.device.support.files.StateFolder;
import org.tinysep.device.support.intake.SourceGate;
import org.tinysep.device.support.lifecycle.AbstractDriver;

/**
 * Time Controller driver (thesis 4.4.3.4): creates its single device at once, opens the synchroniser link and
 * offers {@code tinysep:time}. A changed {@code mode} is applied in place ({@link Modified}): device, connections
 * and listeners stay. A changed port or bind address re-opens the link and re-creates the device.
 */
@Component(service = {}, immediate = true, configurationPid = TimeControllerDriver.PID)
@Designate(ocd = TimeControllerConfig.class)
public final class TimeControllerDriver extends AbstractDriver {

    public static final String PID = "org.tinysep.timecontroller";
    public static final String NAME = "TimeController";
    /** Driver service property with the bound synchroniser port. */
    public static final String PORT_PROPERTY = "tinysep.sync.port";

    private static final Logger LOG = LoggerFactory.getLogger(TimeControllerDriver.class);

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC)
    private volatile ConfigurationAdmin configAdmin;

    private BundleContext bundleContext;
    private TimeControllerConfig config;
    private volatile TimeControllerDevice device;
    private volatile SyncProtocol protocol;
    private volatile SyncLink link;
    private volatile String linkState = "";
    private volatile Path keyFile;
    private ServiceRegistration<TimeCommands> commands;

    public TimeControllerDriver() {
        super(NAME);
    }

    @Activate
    synchronized void activate(BundleContext bundleContext, TimeControllerConfig config) {
        this.bundleContext = bundleContext;
        this.config = config;
        String problem = null;
        try {
            link = SyncLink.open(config.syncBindAddress(), config.syncPort());
            linkState = "listening on " + link.localAddress();
        } catch (IOException | RuntimeException e) {
            problem = "cannot listen on " + config.syncBindAddress() + ":" + config.syncPort() + ": " + e.getMessage();
            linkState = problem;
            link = null;
        }
        start(bundleContext, link == null ? Map.of() : Map.of(PORT_PROPERTY, link.localPort()));
        ClockMode mode = configuredMode(config, ClockMode.REAL);
        device = addDevice(new TimeControllerDevice(context(), new SyncClock(Instant::now, mode), this::request));
        device.link(linkState);
        device.syncTimeout(config.syncTimeout());
        protocol = new SyncProtocol(context(), device.clock(), auth(config), () -> device.switchTo(ClockMode.REAL,
                "the time synchroniser said BYE: it has finished, so the platform follows the system clock again"),
                gate(config));
        if (link != null) {
            link.start(protocol);
            LOG.info("{} in {} mode; time synchroniser link {}", NAME, mode, linkState);
        } else {
            LOG.error("{} {}", NAME, problem);
            context().event(EventKind.PROBLEM, "Monitoring reduced: the time synchroniser link " + problem
                    + ": a time synchroniser (lock-step or demo time) cannot reach TinySEP, and in lock-step mode "
                    + "platform time, and with it all watching, stands still. Another program may hold the port: "
                    + "stop it, or set another syncPort in etc/" + PID + ".cfg, then restart TinySEP");
        }
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("osgi.command.scope", "tinysep");
        props.put("osgi.command.function", new String[] {"time"});
        commands = bundleContext.registerService(TimeCommands.class, new TimeCommands(this), props);
    }

    /** Who may drive the clock (docs/security.md); a bad allow-list falls back to 127.0.0.1 and ::1. */
    private SourceGate gate(TimeControllerConfig c) {
        try {
            return SourceGate.of(c.syncBindAddress(), c.syncAllowedSources(), 0);
        } catch (IllegalArgumentException e) {
            context().event(EventKind.PROBLEM, "syncAllowedSources: " + e.getMessage()
                    + "; allowing only 127.0.0.1, ::1");
            return SourceGate.of(c.syncBindAddress(), "", 0);
        }
    }

    @Modified
    synchronized void modified(TimeControllerConfig next) {
        if (next.syncPort() != config.syncPort() || !next.syncBindAddress().equals(config.syncBindAddress())
                || !next.syncAllowedSources().equals(config.syncAllowedSources())
                || !next.syncKeyFile().equals(config.syncKeyFile())) {
            LOG.info("{}: synchroniser link moves to {}:{} (key {}); the device is re-created", NAME,
                    next.syncBindAddress(), next.syncPort(), next.syncKeyFile());
            deactivate();
            activate(bundleContext, next);
            return;
        }
        config = next;
        device.syncTimeout(next.syncTimeout());
        device.switchTo(configuredMode(next, device.clock().mode()), "configuration " + PID);
    }

    @Deactivate
    synchronized void deactivate() {
        commands.unregister();
        if (link != null) {
            link.close();
        }
        stop();
    }

    /** The synchroniser key: loaded, or created at first use; without one every TICK is refused (a PROBLEM). */
    private SyncAuth auth(TimeControllerConfig c) {
        keyFile = StateFolder.resolveOrDataArea(c.syncKeyFile(), bundleContext, "sync.key");
        if (keyFile == null) {
            context().event(EventKind.PROBLEM, "no folder for the time synchroniser key (set syncKeyFile): every "
                    + "TICK is refused");
            return new SyncAuth(null, "no key file");
        }
        try {
            byte[] key = SyncKey.loadOrCreate(keyFile);
            SyncKey.exposure(keyFile).ifPresent(w -> context().event(EventKind.PROBLEM, w));
            return new SyncAuth(key, null);
        } catch (IOException | RuntimeException e) {
            String why = "cannot read or create " + keyFile + ": " + e.getMessage();
            context().event(EventKind.PROBLEM, "time synchroniser key: " + why + "; every TICK is refused");
            return new SyncAuth(null, why);
        }
    }

    private ClockMode configuredMode(TimeControllerConfig c, ClockMode fallback) {
        try {
            return Modes.parse(c.mode());
        } catch (IllegalArgumentException e) {
            context().event(EventKind.PROBLEM, "configuration " + PID + ": " + e.getMessage() + "; staying "
                    + fallback);
            return fallback;
        }
    }

    /** A user asked to switch (device parameter or shell): switch now, and store it so a restart keeps it. */
    void request(ClockMode mode) {
        device.switchTo(mode, "requested");
        ConfigurationAdmin admin = configAdmin;
        if (admin == null) {
            context().event(EventKind.PROBLEM, "no ConfigurationAdmin: mode " + mode + " lasts until a restart");
            return;
        }
        try {
            Configuration c = admin.getConfiguration(PID, "?");
            Dictionary<String, Object> props = c.getProperties() == null ? new Hashtable<>() : c.getProperties();
            if (!mode.name().equals(props.get("mode"))) {
                props.put("mode", mode.name());
                c.update(props);
            }
        } catch (IOException | RuntimeException e) {
            context().event(EventKind.PROBLEM, "mode " + mode + " not stored, lasts until a restart: " + e);
        }
    }

    ClockService clock() {
        return device.clock();
    }

    /** @return the bound synchroniser port, or {@code -} when the link could not be opened */
    String syncPort() {
        SyncLink l = link;
        return l == null ? "-" : Integer.toString(l.localPort());
    }

    String linkState() {
        return linkState;
    }

    /** @return the synchroniser key file, or {@code -} */
    String keyFile() {
        Path k = keyFile;
        return k == null ? "-" : k.toString();
    }

    @Override
    public List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("status", linkState, "time synchroniser link"));
        out.add(Parameter.readOnly("syncPort", syncPort(), "bound UDP port"));
        SyncProtocol p = protocol;
        out.addAll(p == null ? List.of() : p.parameters());
        return out;
    }
}
