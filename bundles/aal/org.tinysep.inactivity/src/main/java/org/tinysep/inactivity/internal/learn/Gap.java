package org.tinysep.inactivity.internal.learn;

import java.time.Duration;

/**
 * A quiet period of the home's history: nothing happened anywhere from {@code start} for {@code length}, while
 * someone was home.
 *
 * @param start  the sighting that began it (its room and time)
 * @param asleep whether it was sleep ({@link SleepRule})
 * @param length how long it lasted
 */
public record Gap(Sighting start, boolean asleep, Duration length) {
}
