/**
 * The time synchroniser's shared secret and its signature, written once for both ends: the Time Controller, which
 * checks every {@code TICK}, and the simulator (and the tools built on it), which signs them (docs/time-sync.md,
 * "Authentication").
 * <p>
 * Bundles do not import this package at run time: bnd copies it into the Time Controller
 * ({@code -conditionalpackage: ...,org.tinysep.link.sync}).
 */
@Version("1.0.0")
package org.tinysep.link.sync;

import org.osgi.annotation.versioning.Version;
