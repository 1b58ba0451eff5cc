package org.tinysep.sms.internal;

import java.nio.file.Path;
import java.util.List;
import org.osgi.framework.BundleContext;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.lifecycle.AbstractDriver;

/**
 * The driver of the {@link ModemDevice}, opened and closed by the SMS channel (not a component of its own: the
 * device follows the channel's state). The device is added the first time the channel is set up (gammu-smsd's
 * spool folder exists) or used, so a TinySEP without SMS shows no modem in ERROR.
 */
final class ModemDriver extends AbstractDriver {

    static final String NAME = "SmsModem";
    private final List<Parameter> settings;
    private ModemDevice device;

    /** The channel's configuration is shown as read-only parameters of the device. */
    ModemDriver(BundleContext context, Path spool, String pidFile, int stuckSeconds) {
        super(NAME);
        this.settings = List.of(
                Parameter.readOnly("spoolFolder", spool, "gammu-smsd's spool folder (outbox/, inbox/, sent/, error/)"),
                Parameter.readOnly("pidFile", pidFile, "gammu-smsd's pid file; empty = not checked"),
                Parameter.readOnly("stuckSeconds", stuckSeconds, "an SMS waiting longer in outbox/ = the modem "
                        + "does not send (unplugged, no network, no credit)"));
        start(context);
    }

    /** Shows the channel's state on the device, adding the device first if it is not there yet. */
    synchronized void show(DeviceStatus s) {
        if (device == null) {
            device = addDevice(new ModemDevice(context(), settings));
        }
        device.show(s);
    }

    /** Removes the device (its backup stays) and the driver. */
    synchronized void close() {
        device = null;
        stop();
    }
}
