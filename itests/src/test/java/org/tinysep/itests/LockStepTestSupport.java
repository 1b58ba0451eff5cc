package org.tinysep.itests;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.ops4j.pax.exam.Option;

/**
 * A platform driven by the real simulator (the {@code org.tinysep.simulator} bundle, which needs the Sun SPOT
 * protocol too) in lock-step: the Time Controller in EXTERNAL mode with its synchroniser on a free port of
 * 127.0.0.1 ({@link TinySepTestSupport#syncPort()}) and the tests' key ({@link #syncKeyArgs()} for the simulator), Inactivity
 * Recognition reading days in UTC like the simulator.
 */
public abstract class LockStepTestSupport extends TinySepTestSupport {

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(simulatorBundles());
        return o;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        putLockStepTime(configs);
        return configs;
    }

    /** @return the simulator bundle and the Sun SPOT protocol bundles it needs; for tests with another base class */
    public static List<Option> simulatorBundles() {
        List<Option> o = new ArrayList<>(sunSpotBundles(5));
        o.add(reactorBundle("org.tinysep.simulator", 5));
        return o;
    }

    /** Puts the Time Controller in EXTERNAL mode with the tests' key and Inactivity Recognition's days in UTC. */
    public static void putLockStepTime(Map<String, Map<String, String>> configs) {
        configs.put("org.tinysep.timecontroller", TestSyncKey.timeConfig("EXTERNAL"));
        configs.put("org.tinysep.inactivity", Map.of("timeZone", "UTC"));
    }

    /** @return the simulator's option for the Time Controller's key: {@code --sync-key <file>} */
    protected static String[] syncKeyArgs() {
        return new String[] {"--sync-key", TestSyncKey.file().toString()};
    }
}
