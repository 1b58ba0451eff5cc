/**
 * The transport-independent part of the AmICA bus radios (thesis 4.4.1): one bus device per node, created on the
 * node's first keep-alive, the per-frame decisions (deliver, create, reject {@code UNKNOWN_NODE}), rejection
 * counting and the framing of commands to nodes. Generic over the <em>route</em> a node was last heard on and
 * its commands go to: a UDP address for the UDP bus radio, the serial port link for the serial one.
 * <p>
 * Bus radio bundles do not import this package at run time: bnd copies the classes into each of them
 * ({@code -conditionalpackage: org.tinysep.device.support.*,org.tinysep.amica.busradio.base}).
 */
@Version("4.1.0")
package org.tinysep.amica.busradio.base;

import org.osgi.annotation.versioning.Version;
