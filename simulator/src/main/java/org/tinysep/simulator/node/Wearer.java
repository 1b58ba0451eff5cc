package org.tinysep.simulator.node;

/**
 * What a person wearing a node is doing, as the node feels it, and since which virtual second.
 *
 * @param state AWAY (out of the flat: out of the radio's range), ACTIVE (moving about), ASLEEP (lying still) or
 *              COLLAPSED (fell: the node plays a fall, then lies still)
 * @param since epoch second the state began
 */
public record Wearer(State state, long since) {

    public enum State { AWAY, ACTIVE, ASLEEP, COLLAPSED }

    public static final Wearer AWAY = new Wearer(State.AWAY, Long.MIN_VALUE);
}
