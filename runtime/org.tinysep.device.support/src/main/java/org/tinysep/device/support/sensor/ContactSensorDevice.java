package org.tinysep.device.support.sensor;

import org.tinysep.api.sensor.OpenState;
import org.tinysep.device.support.DriverContext;

/**
 * A contact (a reed switch on a door or a window): OPEN or CLOSED, UNKNOWN before the first report; listeners and
 * the event log ("door opened") hear changes, and the first report with {@code first = true}.
 *
 * @param <L> the listener interface
 */
public abstract class ContactSensorDevice<L> extends SensorDevice<L, OpenState> {

    private final String word;

    /** @param word what the contact is on, for the event log: "door" gives "door opened" */
    protected ContactSensorDevice(DriverContext context, Source<OpenState> source, String nodeType, String name,
            String word, Class<?>... provides) {
        super(context, source, nodeType, name, provides);
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
