package org.tinysep.sunspot.protocol;

import org.tinysep.link.frame.testing.Recording;

/** Test sink: the shared {@link Recording} as a {@link SunSpotStreamDecoder.Sink}. */
final class RecordingSink extends Recording<SunSpotFrame, RejectReason> implements SunSpotStreamDecoder.Sink {
}
