package org.tinysep.amica.protocol;

/**
 * A payload of thesis Table 3.1, decoded. {@link AmicaPayloads} converts between these records and bytes.
 * <p>
 * The same records serve both directions: a node reports its state with them, and the platform sends
 * {@link LightControl}, {@link SpeakerControl} and {@link HeaterControl} as commands to set it. Which node type a
 * {@link ReedSwitchStatus} (door or window) or a {@link MotionDetection} (movement or pet collar) belongs to is
 * decided by the sending node's types ({@link KeepAlive#nodeTypes()}), not by the payload.
 */
public sealed interface AmicaPayload
        permits KeepAlive, ReedSwitchStatus, MotionDetection, LightControl, SpeakerControl, HeaterControl {
}
