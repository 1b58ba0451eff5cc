/**
 * Drivers and devices from creation to removal: {@link AbstractDriver} and {@link AbstractDevice} (with the
 * package-private parts that do each section of a device: registration, parameters, backup, status, lost and
 * followed providers), the driver patterns ({@link ProviderDeviceDriver}, {@link NodeTypeDriver},
 * {@link SingleDeviceWiring}, {@link WholeFlatDevice}), the {@link DriverContext} a driver hands its devices, the
 * connections between them ({@link Listeners}, {@link ProviderTracker}, {@link ServiceUse}, {@link Consumptions}),
 * parameter values and actuator settings ({@link ParameterValues}, {@link ConfirmedSetting}), {@link Uids},
 * {@link Backups}, {@link Closeables} and {@link Safely} (calls into other bundles' objects that may throw).
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.0.0")
package org.tinysep.device.support.lifecycle;

import org.osgi.annotation.versioning.Version;
