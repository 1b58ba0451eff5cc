package org.tinysep.simulator.node;

import java.util.HashMap;
import java.util.Map;
import org.tinysep.simulator.flat.NodeSpec;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** A simulated Sun SPOT running one or more of the thesis's programs (3.9.2): movement, temperature, light, pet collar. */
public final class SunSpotNode extends SimNode {

    private final SunSpotAddress address;
    private final SunSpotPort port;
    private final Environment env;
    private final RoomConditions conditions;
    private final Map<String, SunSpotPayload> lastReported = new HashMap<>();

    SunSpotNode(NodeSpec spec, SunSpotPort port, Environment env, RoomConditions conditions) {
        super(spec);
        this.address = SunSpotAddress.parse(spec.address());
        this.port = port;
        this.env = env;
        this.conditions = conditions;
    }

    @Override
    protected int report(long t, long elapsed) {
        int changed = 0;
        if (Rates.due(elapsed, Rates.MOTION) && spec.has("movement")) {
            changed += send("movement", new MovementDetection(env.personMotion(spec.room(), t - Rates.MOTION, t)));
        }
        if (Rates.due(elapsed, Rates.PET_COLLAR) && spec.has("pet-collar")) {
            String pet = spec.carriedBy();
            changed += send("pet", new PetMovementDetection(pet != null && env.petMotion(pet, t - Rates.PET_COLLAR, t)));
        }
        if (Rates.due(elapsed, Rates.SUNSPOT_STATUS) && spec.has("temperature")) {
            changed += send("temperature", TemperatureStatus.ofTenths(conditions.temperatureTenths(spec.room(), t)));
        }
        if (Rates.due(elapsed, Rates.SUNSPOT_STATUS) && spec.has("light-sensor")) {
            changed += send("light", new LightStatus(conditions.brightness(spec.room(), t)));
        }
        return changed;
    }

    private int send(String kind, SunSpotPayload payload) {
        port.send(address, payload);
        return payload.equals(lastReported.put(kind, payload)) ? 0 : 1;
    }
}
