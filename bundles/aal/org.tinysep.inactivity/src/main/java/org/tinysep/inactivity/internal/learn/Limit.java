package org.tinysep.inactivity.internal.learn;

import java.time.Duration;

/**
 * The limit of a quiet period and why.
 *
 * @param limit       how long the quiet period may last before help is called
 * @param asleep      whether the person is taken to be asleep
 * @param explanation in plain words, e.g. "usually at most 40 min between 13:00 and 16:00 in Bathroom, from 21
 *                    days ..." or "fixed limit for rooms of type Bathroom: 45 min (not enough history yet)"
 */
public record Limit(Duration limit, boolean asleep, String explanation) {
}
