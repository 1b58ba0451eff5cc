package org.tinysep.device.support.sensor;

import org.tinysep.api.sensor.OpenState;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * A contact (a reed switch on a door or a window): OPEN or CLOSED, UNKNOWN before the first report; listeners and
 * the event log ("door opened") hear changes, and the first report with {@code first = true}. A contact sensor
 * declares its listener call to the constructor ({@code DoorListener::doorChanged}); it does not override
 * {@code tell}.
 *
 * @param <L> the listener interface
 */
public abstract class ContactSensorDevice<L> extends SensorDevice<L, OpenState> {

    private final String word;

    /**
     * @param word     what the contact is on, for the event log: "door" gives "door opened"
     * @param provides the provider interface, e.g. {@code DoorProvider.class}
     * @param call     the listener call, e.g. {@code DoorListener::doorChanged}
     */
    protected <P> ContactSensorDevice(DriverContext context, Source<OpenState> source, String nodeType, String name,
            String word, Class<P> provides, ListenerCall<L, ? super P, OpenState> call) {
        super(context, source, nodeType, name, provides, call);
        this.word = word;
    }

    /** @return OPEN for true */
    public static OpenState open(boolean open) {
        return open ? OpenState.OPEN : OpenState.CLOSED;
    }

    @Override
    protected final String describe(OpenState state) {
        return word + (state == OpenState.OPEN ? " opened" : " closed");
    }

    /** @return open, closed, or unknown before the first report */
    public final OpenState state() {
        return latestOr(OpenState.UNKNOWN);
    }

    @Override
    protected final Object shownState() {
        return state();
    }
}
