package org.tinysep.simulator.replay;

import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;

/** The state a node enters in a {@link NodeAction}; it keeps reporting that state at its rate until the next one. */
public enum Signal {
    /** Movement / pet-collar node: motion detected ({@code 100 5 0 1}). */
    MOTION_ON,
    /** Movement / pet-collar node: no motion ({@code 100 5 0 0}). */
    MOTION_OFF,
    /** Reed switch (door, window): open ({@code 100 3 0 1}); a presence node (mat, flush, appliance): ON. */
    CONTACT_OPEN,
    /** Reed switch (door, window): closed ({@code 100 3 0 0}); a presence node: OFF. */
    CONTACT_CLOSED;

    /** @return the AmICA payload a node in this state sends */
    public AmicaPayload payload() {
        switch (this) {
            case MOTION_ON: return new MotionDetection(true);
            case MOTION_OFF: return new MotionDetection(false);
            case CONTACT_OPEN: return new ReedSwitchStatus(true);
            default: return new ReedSwitchStatus(false);
        }
    }

    /** @return the signal a node of this kind (motion or contact) enters for a sensor turning on or off */
    static Signal of(boolean motionNode, boolean on) {
        if (motionNode) {
            return on ? MOTION_ON : MOTION_OFF;
        }
        return on ? CONTACT_OPEN : CONTACT_CLOSED;
    }
}
