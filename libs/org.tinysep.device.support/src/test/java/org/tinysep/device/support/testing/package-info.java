/**
 * Test doubles of bus devices for the unit tests of abstraction devices, a {@link
 * org.tinysep.device.support.testing.MutableClock} and a {@link org.tinysep.device.support.testing.FakeHouse} (1.3.0);
 * never part of a deployed bundle.
 */
@Version("1.3.0")
package org.tinysep.device.support.testing;

import org.osgi.annotation.versioning.Version;
