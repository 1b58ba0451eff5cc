package org.tinysep.itests.sunspotabs;

import java.util.List;
import java.util.Map;
import org.ops4j.pax.exam.Option;
import org.tinysep.itests.TinySepTestSupport;

/** The default provisioning plus every Sun SPOT bundle, with the Sun SPOT bus radio on a free port of 127.0.0.1. */
abstract class SunSpotTestSupport extends TinySepTestSupport {

    /** ConfigAdmin pid of the Sun SPOT bus radio. */
    static final String SUN_SPOT_PID = "org.tinysep.sunspot.busradio";
    /** Driver name of the Sun SPOT bus radio; its Driver service carries the bound port. */
    static final String SUN_SPOT_BUS = "BusRadioSunSpot";

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(sunSpotBundles(5));
        return o;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put(SUN_SPOT_PID, Map.of("udpPort", "0", "udpBindAddress", "127.0.0.1"));
        return configs;
    }
}
