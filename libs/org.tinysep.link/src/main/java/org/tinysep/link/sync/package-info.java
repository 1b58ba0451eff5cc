/**
 * The time synchroniser's shared secret and its signature, written once for both ends: the Time Controller, which
 * checks every {@code TICK}, and the simulator (and the tools built on it), which signs them (docs/time-sync.md,
 * "Authentication"). {@link org.tinysep.link.sync.SyncSecret#hmacHex} (1.1.0) is the one HMAC-SHA256 of TinySEP's
 * signed messages, also under the signed JSON messages of {@code org.tinysep.json.JsonSignature}.
 * <p>
 * Bundles do not import this package at run time: bnd copies it into the Time Controller and into every user of
 * {@code org.tinysep.json} ({@code -conditionalpackage: ...,org.tinysep.link.sync}).
 */
@Version("1.1.0")
package org.tinysep.link.sync;

import org.osgi.annotation.versioning.Version;
