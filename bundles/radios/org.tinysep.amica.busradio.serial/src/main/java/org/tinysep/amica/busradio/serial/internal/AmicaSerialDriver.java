package org.tinysep.amica.busradio.serial.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.device.support.lifecycle.AbstractDriver;
import org.tinysep.device.support.time.PlatformTicker;

/**
 * Bus Radio AmICA (serial), thesis 4.4.1.1: one instance per factory configuration, i.e. per serial port, named
 * {@code BusRadioAmicaSerial <port>}. The modified AmICA base node on the port forwards the frames of every node
 * in range; the shared AmICA bus radio logic creates one bus device per node on its first keep-alive. Its Driver
 * service carries the port ({@value #PORT_PROPERTY}).
 */
@Component(service = {}, immediate = true, configurationPid = AmicaSerialDriver.PID,
        configurationPolicy = ConfigurationPolicy.REQUIRE)
@Designate(ocd = BusRadioSerialConfig.class, factory = true)
public final class AmicaSerialDriver extends AbstractDriver {

    public static final String PID = "org.tinysep.amica.busradio.serial";
    public static final String NAME = "BusRadioAmicaSerial";
    public static final String PORT_PROPERTY = "tinysep.serial.port";

    private static final Logger LOG = LoggerFactory.getLogger(AmicaSerialDriver.class);

    private final SerialSettings settings;
    private final NodePolicy policy;
    private final List<String> policyProblems = new ArrayList<>();
    private volatile SerialRadio radio;
    private volatile PlatformTicker ticker;

    /** DS constructor injection: the configuration names the driver (one per port). */
    @Activate
    public AmicaSerialDriver(BusRadioSerialConfig config, Map<String, Object> properties) {
        super(SerialSettings.of(config, properties).driverName());
        this.settings = SerialSettings.of(config, properties);
        this.policy = SerialSettings.policy(config, properties, policyProblems);
    }

    @Activate
    void activate(BundleContext bundleContext) {
        start(bundleContext, settings.port() == null ? Map.of() : Map.of(PORT_PROPERTY, settings.port()));
        List<String> problems = new ArrayList<>(settings.problems());
        problems.addAll(policyProblems);
        for (String problem : problems) {
            LOG.warn("{}: {}", name(), problem);
            context().event(EventKind.PROBLEM, problem);
        }
        if (settings.port() != null) {
            SerialRadio r = new SerialRadio(context(), settings, this::addDevice);
            radio = r;
            r.policy(policy);
            r.restore(savedDevices()); // known nodes as they were, before the port opens (docs/backup.md)
            r.start();
            ticker = new PlatformTicker(bundleContext, name(), r::tick); // sensor health in platform time
        }
    }

    @Deactivate
    void deactivate() {
        stop(ticker, radio); // then removes the bus devices one by one (each leaves the node table), the driver
    }

    @Override
    public List<Parameter> parameters() {
        SerialRadio r = radio;
        if (r == null) {
            return List.of(Parameter.readOnly("status", "not running: " + String.join("; ", settings.problems()),
                    "serial port state"));
        }
        return r.parameters();
    }
}
