/**
 * The one UDP link of the platform ({@link org.tinysep.link.udp.DatagramLink}), shared by the AmICA UDP bus radio,
 * the Sun SPOT bus radio's UDP link and the Time Controller's synchroniser link: one receive loop on its own
 * {@link org.tinysep.link.udp.LinkThread}, a drain for the lock-step tick, and sends on the caller's thread. The
 * Sun SPOT bus radio's SDK link runs on a {@code LinkThread} too.
 * <p>
 * Bundles do not import this package at run time: bnd copies it into each of them
 * ({@code -conditionalpackage: ...,org.tinysep.link.udp}); they import {@code org.slf4j}.
 */
@Version("1.1.0")
package org.tinysep.link.udp;

import org.osgi.annotation.versioning.Version;
