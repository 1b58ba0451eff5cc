/**
 * Platform time: {@link PlatformClock} (the Time Controller's time when present, else the system clock),
 * {@link PlatformTicker} (one tick per platform second, or only when the component is {@link Due}) and
 * {@link Backoff} (exponential back-off as a value).
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.1.0")
package org.tinysep.device.support.time;

import org.osgi.annotation.versioning.Version;
