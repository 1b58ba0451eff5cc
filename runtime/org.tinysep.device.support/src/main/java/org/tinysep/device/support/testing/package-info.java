/** Test doubles of bus devices for the unit tests of abstraction devices; never part of a deployed bundle. */
@Version("1.2.0")
package org.tinysep.device.support.testing;

import org.osgi.annotation.versioning.Version;
