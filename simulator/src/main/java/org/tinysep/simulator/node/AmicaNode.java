package org.tinysep.simulator.node;

import java.util.HashMap;
import java.util.Map;
import java.util.function.Consumer;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.simulator.flat.NodeSpec;

/**
 * A simulated AmICA node of one or more types. Sensors report what the {@link Environment} shows; lights, heaters
 * and speakers report their value every 10 s and take Light/Heater/Speaker Control commands, which change the
 * value and are answered at once with a status frame.
 */
public final class AmicaNode extends SimNode {

    private final AmicaPort port;
    private final Environment env;
    private final Consumer<String> events;
    private final int productId;
    private final long serial;
    private final Map<String, Object> lastReported = new HashMap<>();
    private volatile int light;
    private volatile int heater;
    private volatile int speaker;

    AmicaNode(NodeSpec spec, AmicaPort port, Environment env, Consumer<String> events) {
        super(spec);
        this.port = port;
        this.env = env;
        this.events = events;
        this.productId = AmicaNodeType.productId(spec.types().stream()
                .map(t -> AmicaNodeType.fromTypeName(t).orElseThrow()).toList());
        this.serial = 0x5100_0000L + port.address().netgroup() * 256L + port.address().address();
        this.light = this.heater = this.speaker = spec.initialPercent();
    }

    public AmicaPort port() {
        return port;
    }

    public int light() {
        return light;
    }

    public int heater() {
        return heater;
    }

    @Override
    protected synchronized int report(long t, long elapsed) {
        int changed = 0;
        if (Rates.due(elapsed, Rates.KEEP_ALIVE)) {
            port.sendKeepAlive(elapsed, productId, serial);
        }
        if (Rates.due(elapsed, Rates.MOTION) && spec.has("movement")) {
            changed += send("movement", new MotionDetection(env.personMotion(spec.room(), t - Rates.MOTION, t)));
        }
        if (Rates.due(elapsed, Rates.PET_COLLAR) && spec.has("pet-collar")) {
            String pet = spec.carriedBy();
            changed += send("pet", new MotionDetection(pet != null && env.petMotion(pet, t - Rates.PET_COLLAR, t)));
        }
        if (Rates.due(elapsed, Rates.REED_SWITCH) && (spec.has("door") || spec.has("window"))) {
            changed += send("reed", new ReedSwitchStatus(spec.outerDoor() && env.doorOpen(spec.room(), t)));
        }
        if (Rates.due(elapsed, Rates.ACTUATOR_STATUS)) {
            changed += actuatorStatus();
        }
        return changed;
    }

    private int actuatorStatus() {
        int changed = 0;
        if (spec.has("simple-light") || spec.has("dimmable-light")) {
            changed += send("light", new LightControl(light));
        }
        if (spec.has("heater")) {
            changed += send("heater", new HeaterControl(heater));
        }
        if (spec.has("speaker")) {
            changed += send("speaker", new SpeakerControl(speaker));
        }
        return changed;
    }

    private int send(String kind, AmicaPayload payload) {
        port.send(payload);
        return payload.equals(lastReported.put(kind, payload)) ? 0 : 1;
    }

    /**
     * Handles a command from the platform: sets the value and reports it at once. Ignored while switched off.
     *
     * @return 1 if the answer reports a value different from the node's previous report of that kind, else 0
     */
    public synchronized int command(AmicaPayload payload) {
        if (!powered()) {
            return 0;
        }
        if (payload instanceof LightControl c && (spec.has("simple-light") || spec.has("dimmable-light"))) {
            light = c.percent();
            events.accept(spec.id() + " light " + light + " %");
            return send("light", new LightControl(light));
        } else if (payload instanceof HeaterControl c && spec.has("heater")) {
            heater = c.percent();
            events.accept(spec.id() + " heater " + heater + " %");
            return send("heater", new HeaterControl(heater));
        } else if (payload instanceof SpeakerControl c && spec.has("speaker")) {
            speaker = c.percent();
            events.accept(spec.id() + " speaker " + speaker + " %");
            return send("speaker", new SpeakerControl(speaker));
        }
        events.accept(spec.id() + " ignored a command it cannot carry out: " + payload);
        return 0;
    }
}
