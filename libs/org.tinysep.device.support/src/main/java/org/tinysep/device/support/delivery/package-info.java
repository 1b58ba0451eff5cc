/**
 * Payloads handed from a radio's receive thread to its devices' listeners in order, with a guard against a slow
 * listener: {@link OrderedDelivery} (one bounded queue and one dispatcher per radio, a watchdog that takes a
 * listener inside one call longer than a limit out of the ordered path), {@link GuardedLane} (one listener as the
 * dispatcher sees it) and {@link RateLimitedProblem} (losses said at most once a minute). The AmICA and Sun SPOT
 * bus radios use it.
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.0.0")
package org.tinysep.device.support.delivery;

import org.osgi.annotation.versioning.Version;
