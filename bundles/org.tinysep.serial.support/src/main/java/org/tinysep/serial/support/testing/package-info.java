/**
 * <b>Test utilities, not for production code.</b> Real serial ports for tests without hardware: {@link
 * org.tinysep.serial.support.testing.SocatPair} starts a socat pseudo-terminal pair (what a USB serial adapter and
 * the device behind it look like to a serial link) and {@link org.tinysep.serial.support.testing.PtyPeer} plays the
 * device at the far end. Used by the tests of serial support and of the serial bus radios; they need {@code socat}
 * ({@code scripts/install-deps.sh}).
 * <p>
 * Never part of a deployed bundle: the bus radios copy {@code org.tinysep.serial.support} into themselves with bnd's
 * {@code -conditionalpackage}, which copies only the packages their main code references, and no main code
 * references this one. Main code must not use it.
 */
package org.tinysep.serial.support.testing;
