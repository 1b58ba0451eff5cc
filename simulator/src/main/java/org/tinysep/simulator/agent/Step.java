package org.tinysep.simulator.agent;

/**
 * One scenario line: at {@code secondOfDay}, {@code agent} (or, for {@link Action#BATTERY}, node {@code target})
 * does {@code action}; {@code room}/{@code room2} are exact room names or null; {@code on} is the battery state.
 */
public record Step(int line, int secondOfDay, String agent, Action action, String room, String room2, String target,
        boolean on) {
}
