package org.tinysep.houseinformation.internal;

import java.nio.file.Path;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.device.support.files.StateFolder;
import org.tinysep.device.support.lifecycle.AbstractDriver;

/**
 * House Information driver: creates its single device at once on activation, since it needs nothing else (thesis
 * 3.6, Fig 3.8). A changed configuration restarts the component, so the device reloads from the new file.
 */
@Component(service = {}, immediate = true, configurationPid = HouseInformation.PID)
@Designate(ocd = HouseConfig.class)
public final class HouseInformation extends AbstractDriver {

    static final String PID = "org.tinysep.houseinformation";
    static final String NAME = "HouseInformation";
    static final String HOME = "tinysep.home";
    private static final Logger LOG = LoggerFactory.getLogger(HouseInformation.class);

    public HouseInformation() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, HouseConfig config) {
        start(bundleContext);
        Path file = houseFile(config.file(), bundleContext.getProperty(StateFolder.VAR), bundleContext.getProperty(HOME));
        LOG.info("House Information uses {}", file);
        addDevice(new HouseDevice(context(), new HouseFile(file, new HouseCodec())));
    }

    @Deactivate
    void deactivate() {
        stop();
    }

    /**
     * @return the configured file, else {@code <tinysep.var>/house.xml}, else {@code <home>/var/house.xml}, else
     *         {@code house.xml} in the working directory
     */
    static Path houseFile(String configured, String var, String home) {
        return StateFolder.resolve(configured, var, home, "house.xml")
                .orElseGet(() -> Path.of("house.xml").toAbsolutePath());
    }
}
