package org.tinysep.mqtt.internal;

import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.health.NodeHealth;

/** A device's health in one plain sentence. */
final class HealthText {

    private HealthText() {
    }

    static String explain(String where, DeviceStatus status, NodeHealth node) {
        StringBuilder b = new StringBuilder(where).append(": ");
        if (node != null && !node.online()) {
            b.append(node.lastHeard() == null ? "not heard since the platform started"
                    : "silent since " + node.lastHeard() + " (it should report every "
                            + node.reportInterval().toSeconds() + " s)");
        } else if (status == null) {
            b.append("status unknown");
        } else {
            b.append(switch (status.state()) {
                case ONLINE -> "working";
                case OFFLINE -> "offline";
                case ERROR -> "needs attention";
                case UNKNOWN -> "no report yet";
            });
            if (!status.detail().isEmpty()) {
                b.append(" (").append(status.detail()).append(')');
            }
        }
        if (node != null && node.batteryLow()) {
            b.append("; battery low (").append(node.batteryMillivolts()).append(" mV), replace it soon");
        }
        return b.toString();
    }
}
