package org.tinysep.itests;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.ops4j.pax.exam.Option;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;

/**
 * A platform driven by the real simulator (the {@code org.tinysep.simulator} bundle, which needs the Sun SPOT
 * protocol too) in lock-step: the Time Controller in EXTERNAL mode with its synchroniser on a free port of
 * 127.0.0.1 ({@link #syncPort()}) and the tests' key ({@link #syncKeyArgs()} for the simulator), Inactivity
 * Recognition reading days in UTC like the simulator.
 */
public abstract class LockStepTestSupport extends TinySepTestSupport {

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(sunSpotBundles(5));
        o.add(reactorBundle("org.tinysep.simulator", 5));
        return o;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        configs.put("org.tinysep.timecontroller", TestSyncKey.timeConfig("EXTERNAL"));
        configs.put("org.tinysep.inactivity", Map.of("timeZone", "UTC"));
        return configs;
    }

    /** @return the simulator's option for the Time Controller's key: {@code --sync-key <file>} */
    protected static String[] syncKeyArgs() {
        return new String[] {"--sync-key", TestSyncKey.file().toString()};
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
}
