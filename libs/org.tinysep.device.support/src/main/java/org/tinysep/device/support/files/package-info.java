/**
 * Files that must survive a crash and where they live: {@link AtomicFiles} (temp, force, atomic rename, folder sync),
 * {@link AtomicBatch} (many writes, one folder sync), {@link StateFolder} (a component's state folder) and
 * {@link TrustedCertificates} (a TLS socket factory from one PEM file, read at every call).
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.0.0")
package org.tinysep.device.support.files;

import org.osgi.annotation.versioning.Version;
