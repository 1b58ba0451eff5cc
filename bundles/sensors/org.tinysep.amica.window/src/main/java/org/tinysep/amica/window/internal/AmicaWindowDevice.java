package org.tinysep.amica.window.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.WindowListener;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.ContactSensorDevice;
import org.tinysep.device.support.sensor.Source;

/**
 * Abstracts one AmICA reed switch on a window: Reed-Switch Status payloads (100 3 0 A) become window states.
 * Listeners and the event log hear changes only (the node repeats its state every second); the first report
 * establishes the state ({@code first}), it is not a change. The user may give the window's position, which
 * listeners hear as {@code windowPositionChanged}.
 */
final class AmicaWindowDevice extends ContactSensorDevice<WindowListener> implements WindowProvider {

    private volatile Optional<Coordinates> position = Optional.empty();

    AmicaWindowDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Source.amica(bus, AmicaPayloads::decode, ReedSwitchStatus.class, (r, at) -> open(r.open())),
                NodeType.WINDOW, "Window " + bus.nodeId(), "window", WindowProvider.class,
                WindowListener::windowChanged);
    }

    @Override
    public Optional<Coordinates> position() {
        return position;
    }

    @Override
    protected List<Parameter> settings() {
        return List.of(Parameter.writable("position", Positions.format(position),
                "x,y,z in metres in the house's frame, empty when unknown"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"position".equals(key)) {
            throw unknownParameter(key);
        }
        Optional<Coordinates> next = Positions.parse(value);
        if (next.equals(position)) {
            return;
        }
        position = next;
        if (next.isEmpty()) {
            event("window position cleared"); // WindowListener has no event for "no position"
            return;
        }
        Coordinates c = next.get();
        event("window position set to " + Positions.format(next) + " m");
        Instant at = now();
        fire(l -> l.windowPositionChanged(this, c, at));
    }
}
