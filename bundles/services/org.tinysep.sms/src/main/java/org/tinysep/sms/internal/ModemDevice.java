package org.tinysep.sms.internal;

import java.util.List;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;

/**
 * The GSM modem behind gammu-smsd as a device in the platform's device list: ONLINE while SMS can go
 * out, ERROR in plain words while they cannot ("the GSM modem cannot send SMS: gammu-smsd is not running ..."),
 * with the words of {@link ModemHealth}. It provides no interface: the SMS channel is the
 * {@code MessageChannel} service; this device is what a caregiver sees in {@code tinysep:devices} and the console.
 */
final class ModemDevice extends WholeFlatDevice {

    static final String TYPE = "SmsModem";
    private final List<Parameter> settings;

    ModemDevice(DriverContext context, List<Parameter> settings) {
        super(context, Uids.of(context.driverName(), "modem"), TYPE, "GSM modem (gammu-smsd)");
        this.settings = List.copyOf(settings);
    }

    /** Follows the SMS channel's state; a change is a STATUS entry in the event log. */
    void show(DeviceStatus s) {
        status(s.state(), words(s));
    }

    /** @return the status text of the device for the channel's status {@code s} */
    static String words(DeviceStatus s) {
        return s.state() == DeviceStatus.State.ERROR ? "the GSM modem cannot send SMS: " + s.detail() : s.detail();
    }

    @Override
    protected List<Parameter> moreParameters() {
        return settings;
    }
}
