package org.tinysep.amica.door.internal;

import java.util.List;
import java.util.Locale;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.ContactSensorDevice;
import org.tinysep.device.support.sensor.Source;

/**
 * Abstracts one AmICA reed switch on a door: Reed-Switch Status payloads (100 3 0 A) become door states.
 * Listeners and the event log hear changes only (the node repeats its state every second); the first report
 * establishes the state ({@code first}), it is not a change. The user sets whether the door is OUTER or INNER.
 */
final class AmicaDoorDevice extends ContactSensorDevice<DoorListener> implements DoorProvider {

    private volatile DoorKind kind = DoorKind.OUTER;

    AmicaDoorDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Source.amica(bus, AmicaPayloads::decode, ReedSwitchStatus.class, (r, at) -> open(r.open())),
                NodeType.DOOR, "Door " + bus.nodeId(), "door", DoorProvider.class, DoorListener::doorChanged);
    }

    @Override
    public DoorKind kind() {
        return kind;
    }

    @Override
    protected List<Parameter> settings() {
        return List.of(Parameter.writable("kind", kind, "OUTER (to the outside; watched by Flat Occupancy) or INNER"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"kind".equals(key)) {
            throw unknownParameter(key);
        }
        try {
            kind = DoorKind.valueOf(value.strip().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException | NullPointerException e) {
            throw new IllegalArgumentException("kind must be OUTER or INNER, was '" + value + "'");
        }
        event("door kind set to " + kind);
    }
}
