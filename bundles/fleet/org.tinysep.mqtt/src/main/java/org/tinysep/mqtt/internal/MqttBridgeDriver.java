package org.tinysep.mqtt.internal;

import java.nio.file.Path;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.files.StateFolder;
import org.tinysep.device.support.lifecycle.AbstractDriver;

/**
 * The MQTT bridge: like the Mail Manager a driver with its one device, created at once. Installed by
 * default and idle until {@code brokerUrl} is configured; a configuration change replaces the running bridge.
 */
@Component(service = {}, immediate = true, configurationPid = MqttBridgeDriver.PID)
@Designate(ocd = MqttConfig.class)
public final class MqttBridgeDriver extends AbstractDriver {

    public static final String PID = "org.tinysep.mqtt";
    public static final String NAME = "MqttBridge";

    private static final Logger LOG = LoggerFactory.getLogger(MqttBridgeDriver.class);

    private Path var;
    private BridgeDevice device;

    public MqttBridgeDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, Map<String, Object> properties) {
        var = StateFolder.resolveOrDataArea(null, bundleContext, "mqtt").getParent();
        start(bundleContext);
        Parsed p = parse(properties);
        device = addDevice(new BridgeDevice(context(), p.settings, p.problem));
    }

    @Modified
    void modified(Map<String, Object> properties) {
        Parsed p = parse(properties);
        device.reconfigure(p.settings, p.problem);
    }

    @Deactivate
    void deactivate() {
        stop();
    }

    private record Parsed(Settings settings, String problem) {
    }

    private Parsed parse(Map<String, Object> properties) {
        try {
            Settings s = Settings.parse(properties, var);
            LOG.info("{}: {}", NAME, s.configured() ? "configured for " + s.redacted()
                    : "idle, no brokerUrl configured (configuration " + PID + ")");
            return new Parsed(s, null);
        } catch (IllegalArgumentException e) {
            String problem = "configuration " + PID + " refused: " + e.getMessage();
            LOG.warn("{}; the MQTT bridge stays idle until it is fixed", problem);
            context().event(EventKind.PROBLEM, problem);
            return new Parsed(Settings.parse(Map.of(), var), e.getMessage());
        }
    }
}
