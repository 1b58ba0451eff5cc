package org.tinysep.api.health;

import java.time.Duration;
import java.time.Instant;
import java.util.Objects;
import java.util.Set;

/**
 * The health of one hardware node as its bus device sees it, at one instant of platform time.
 *
 * @param deviceUid          the bus device's UID
 * @param nodeAddress        the node address, e.g. {@code 1.17} (AmICA) or {@code 0014.4F01.0000.1234} (Sun SPOT)
 * @param nodeTypes          the node's types ({@code NodeType} names)
 * @param online             false while the node is silent (or its link is down, or not heard since a restart)
 * @param lastHeard          the platform time of its last valid frame; null if never heard
 * @param silentSince        when the silence that made it OFFLINE began (its last frame), null while online
 * @param reportInterval     the shortest report interval its node types promise (thesis 3.9)
 * @param batteryMillivolts  the battery voltage of the last keep-alive; null when the protocol carries none
 * @param batteryLow         whether that voltage is below the configured low-battery level
 * @param received           valid frames received in the link-quality window
 * @param expected           reports the node's types promise in the same window (0 until it has lasted a report
 *                           interval)
 * @param sequenceGaps       frames missing by sequence number since the node was first heard (AmICA); 0 when the
 *                           protocol has no sequence numbers
 */
public record NodeHealth(String deviceUid, String nodeAddress, Set<String> nodeTypes, boolean online,
        Instant lastHeard, Instant silentSince, Duration reportInterval, Integer batteryMillivolts,
        boolean batteryLow, long received, long expected, long sequenceGaps) {

    public NodeHealth {
        Objects.requireNonNull(deviceUid, "deviceUid");
        Objects.requireNonNull(nodeAddress, "nodeAddress");
        nodeTypes = Set.copyOf(nodeTypes);
        Objects.requireNonNull(reportInterval, "reportInterval");
    }

    /**
     * @return received vs expected reports in the window as a percentage, 0..100 (thesis Table 5.4), or -1 while
     *         nothing is expected yet
     */
    public int linkQualityPercent() {
        if (expected <= 0) {
            return -1;
        }
        return (int) Math.min(100, Math.round(100.0 * received / expected));
    }
}
