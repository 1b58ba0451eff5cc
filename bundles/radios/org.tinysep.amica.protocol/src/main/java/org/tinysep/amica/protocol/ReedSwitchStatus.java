package org.tinysep.amica.protocol;

/**
 * Reed-Switch Status payload {@code 100 3 0 A}: A = 0 closed, A = 1 open. Sent by door and window nodes.
 *
 * @param open true if the door or window is open
 */
public record ReedSwitchStatus(boolean open) implements AmicaPayload {
}
