package org.tinysep.amica.presence.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.api.sensor.presence.PresenceListener;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.SensorDevice;
import org.tinysep.device.support.sensor.Source;

/**
 * Abstracts one AmICA presence node (a bed or seat mat, a flush, an appliance): Reed-Switch Status payloads
 * (100 3 0 A, A = 1 ON) become presence ON/OFF. Its kind comes from the node type the keep-alive announced.
 * Listeners and the event log hear changes only (the node repeats its state every second); the first report
 * establishes the state ({@code first}), it is not a change. The event-log words are the kind and on/off
 * ("seat on", "bed off"): Inactivity Recognition learns from exactly these entries in the log's history.
 */
final class AmicaPresenceDevice extends SensorDevice<PresenceListener, Boolean> implements PresenceProvider {

    private final PresenceKind kind;

    AmicaPresenceDevice(DriverContext context, BusRadioAmicaProvider bus) {
        this(context, bus, PresenceNodeKind.of(bus.nodeTypes()));
    }

    private AmicaPresenceDevice(DriverContext context, BusRadioAmicaProvider bus, PresenceKind kind) {
        super(context, Source.amica(bus, AmicaPayloads::decode, ReedSwitchStatus.class, (r, at) -> r.open()),
                PresenceNodeKind.typeName(kind), PresenceNodeKind.defaultName(kind, bus.nodeId()),
                PresenceProvider.class);
        this.kind = kind;
    }

    @Override
    protected void tell(PresenceListener listener, Boolean present, boolean first, Instant at) {
        listener.presenceChanged(this, present, first, at);
    }

    @Override
    protected String describe(Boolean present) {
        return kind.name().toLowerCase(Locale.ROOT) + (present ? " on" : " off");
    }

    @Override
    public PresenceKind kind() {
        return kind;
    }

    @Override
    public boolean present() {
        return latestOr(false);
    }

    @Override
    protected Object shownState() {
        Boolean p = latest();
        return p == null ? "UNKNOWN" : p ? "ON" : "OFF";
    }

    @Override
    protected List<Parameter> readings() {
        List<Parameter> all = new ArrayList<>();
        all.add(Parameter.readOnly("kind", kind, "what it observes, from the node type: BED, SEAT (someone is here "
                + "while ON), FLUSH, APPLIANCE (activity when it turns on or off)"));
        all.addAll(super.readings());
        return all;
    }
}
