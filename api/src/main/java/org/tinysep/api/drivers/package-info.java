/**
 * The drivers list (thesis 3.4, Fig 3.5) as a service: which applications the platform runs, from
 * {@code ${tinysep.var}/drivers.xml}, and the changes an operator makes to it. Provided by the bundle
 * {@code org.tinysep.drivers}; its shell commands ({@code tinysep:drivers}) and the web API use it.
 */
@Export
@Version("1.0.0")
package org.tinysep.api.drivers;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
