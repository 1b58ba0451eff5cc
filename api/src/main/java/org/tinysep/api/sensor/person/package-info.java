/**
 * The person node: a Sun SPOT worn by the person at the waist or as a pendant. It reports its two
 * switches, a movement summary every few seconds and, around any acceleration peak, the raw samples. Applications
 * (help button, fall detection, per-person activity) consume it through {@link PersonNodeProvider}; the node's
 * protocol is in {@code docs/protocols/sunspot.md} ("Person node").
 */
@Export
@Version("1.1.0")
package org.tinysep.api.sensor.person;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
