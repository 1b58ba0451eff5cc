package org.tinysep.mailmanager.internal;

import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.service.MailStatus;

/**
 * Where alerts go, in plain words, for the device status, the driver's figures and the Driver service properties
 * (README, "Status"). An undelivered alert keeps the device out of ONLINE until a message is delivered to all its
 * recipients.
 *
 * @param settings      the settings in use
 * @param configProblem why the configuration was refused, or null
 * @param mail          the outbox status
 * @param detail        the outbox status detail (e.g. why it is retrying)
 * @param undelivered   why an alert was not delivered, or null
 */
record MailHealth(MailSettings settings, String configProblem, MailStatus mail, String detail, String undelivered) {

    static final String NO_HOST = "no SMTP host configured: alerts are only written to the log";

    /** Values of the Driver service property {@value MailManagerDriver#DELIVERY_PROPERTY}. */
    static final String NONE = "none";
    static final String INVALID = "invalid";
    static final String SMTP = "smtp";

    /** @return {@link #NONE}, {@link #INVALID} or {@link #SMTP} */
    String delivery() {
        return configProblem != null ? INVALID : settings.configured() ? SMTP : NONE;
    }

    /** @return one sentence: where alerts go and what is wrong, if anything */
    String summary() {
        String base = switch (delivery()) {
            case INVALID -> "bad configuration (" + configProblem + "): alerts are only written to the log until it"
                    + " is fixed";
            case NONE -> NO_HOST;
            default -> "alerts are mailed through " + settings.host() + ":" + settings.port() + " to "
                    + String.join(", ", settings.recipients());
        };
        String retrying = mail == MailStatus.RETRYING && detail != null && !detail.isEmpty() ? "; " + detail : "";
        return (undelivered == null ? "" : undelivered + "; ") + base + retrying;
    }

    DeviceStatus.State state() {
        if (undelivered != null || configProblem != null) {
            return DeviceStatus.State.ERROR;
        }
        if (!settings.configured()) {
            return DeviceStatus.State.UNKNOWN;
        }
        return mail == MailStatus.RETRYING ? DeviceStatus.State.OFFLINE : DeviceStatus.State.ONLINE;
    }

    /** @return the device status detail */
    String statusDetail() {
        if (state() == DeviceStatus.State.ONLINE) {
            return mail == MailStatus.SENDING ? detail : "";
        }
        return summary();
    }
}
