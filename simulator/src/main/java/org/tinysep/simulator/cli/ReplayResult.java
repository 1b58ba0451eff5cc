package org.tinysep.simulator.cli;

import java.time.Duration;

/**
 * What a replay did.
 *
 * @param replay   the plan and its placement in virtual time
 * @param sent     recorded actions sent (all of them after a complete run)
 * @param played   virtual seconds played (ticked in lock-step)
 * @param wallTime how long it took
 */
public record ReplayResult(Replay replay, int sent, long played, Duration wallTime) {
}
