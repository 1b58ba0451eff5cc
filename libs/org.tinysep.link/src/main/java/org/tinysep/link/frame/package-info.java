/**
 * What the AmICA and the Sun SPOT node protocols share, written once: the frame layout (size identifier S first,
 * a CRC-8/SMBUS checksum byte followed by the payload length L, then S payload bytes), the checks a frame must pass
 * and the reasons it fails ({@link org.tinysep.link.frame.FrameFormat}), and the byte-stream skeleton that finds
 * frames after garbage ({@link org.tinysep.link.frame.FrameStream}). Each family subclasses {@code FrameFormat} with
 * its header rules, its reason enum and its frame record.
 * <p>
 * Plain Java without OSGi or logging imports. Bundles do not import this package at run time: bnd copies it into
 * each protocol bundle ({@code -conditionalpackage: org.tinysep.link.frame}), and no exported signature names its
 * types, so the protocol packages' APIs are unchanged.
 */
@Version("3.1.0")
package org.tinysep.link.frame;

import org.osgi.annotation.versioning.Version;
