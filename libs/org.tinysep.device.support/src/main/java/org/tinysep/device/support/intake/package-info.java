/**
 * What a bus radio takes in and what it refuses: {@link PacketIntake} (the decoder path of both node families),
 * {@link SourceGate} (who may send to a UDP link), {@link RejectCounter}, {@link RejectSampler} and
 * {@link RejectTotals} (rejected input counted, sampled into the packet log, summed) and {@link FrameWords} (a node
 * frame in words for the packet describers).
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.0.0")
package org.tinysep.device.support.intake;

import org.osgi.annotation.versioning.Version;
