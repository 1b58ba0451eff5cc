package org.tinysep.itests.sunspotabs;

import java.util.List;
import java.util.Map;
import org.ops4j.pax.exam.Option;
import org.tinysep.itests.TinySepTestSupport;

/**
 * The default provisioning plus every Sun SPOT bundle, with the Sun SPOT bus radio on a free port of 127.0.0.1
 * ({@link #sunSpotConfiguration()}); for the Sun SPOT abstraction and bus radio tests.
 */
public abstract class SunSpotTestSupport extends TinySepTestSupport {

    /** Driver name of the Sun SPOT bus radio; its Driver service carries the bound port. */
    protected static final String SUN_SPOT_BUS = "BusRadioSunSpot";

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(sunSpotBundles(5));
        return o;
    }

    /** @return the Sun SPOT bus radio's configuration: UDP on a free port of 127.0.0.1 */
    protected Map<String, String> sunSpotConfiguration() {
        return Map.of("udpPort", "0", "udpBindAddress", "127.0.0.1");
    }

    @Override
    protected final Map<String, Map<String, String>> initialConfigurations() {
        return replacing(super.initialConfigurations(), SUN_SPOT_PID, sunSpotConfiguration());
    }
}
