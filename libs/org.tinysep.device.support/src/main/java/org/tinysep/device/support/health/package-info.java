/**
 * Sensor health of a bus device's node in platform time: {@link NodeWatch} (last heard, silences, damped flapping,
 * received vs promised reports), {@link ReportRates} (the report periods the node types promise), {@link NodePolicy}
 * (a bus radio's health and capacity settings) and {@link HealthWords} (the plain words of the event log).
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.1.0")
package org.tinysep.device.support.health;

import org.osgi.annotation.versioning.Version;
