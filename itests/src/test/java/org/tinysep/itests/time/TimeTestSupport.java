package org.tinysep.itests.time;

import java.util.LinkedHashMap;
import java.util.Map;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.TestSyncKey;
import org.tinysep.itests.TinySepTestSupport;

/** Time Controller tests: its link on a free port of 127.0.0.1, starting in {@link #initialMode()}. */
abstract class TimeTestSupport extends TinySepTestSupport {

    static final String TIME_PID = "org.tinysep.timecontroller";

    /** @return REAL or EXTERNAL */
    abstract String initialMode();

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        configs.put(TIME_PID, TestSyncKey.timeConfig(initialMode()));
        return configs;
    }

    /** @return the configuration as first written, with another mode */
    static Map<String, Object> config(String mode) {
        return Map.copyOf(TestSyncKey.timeConfig(mode));
    }


    TimeControllerProvider clock() {
        return awaitService(TimeControllerProvider.class, null, TIMEOUT);
    }
}
