package org.tinysep.amica.protocol;

import org.tinysep.link.frame.testing.Recording;

/** Test sink: the shared {@link Recording} as a {@link AmicaStreamDecoder.Sink}. */
final class RecordingSink extends Recording<AmicaFrame, RejectReason> implements AmicaStreamDecoder.Sink {
}
