package org.tinysep.amica.protocol;

import java.util.ArrayList;
import java.util.List;

/**
 * The resynchronisation rule of {@code docs/protocols/amica.md} ("Transports", serial), written as plainly as
 * possible over a whole stream at once: look for a frame at the first byte; emit it if valid, otherwise drop that
 * one byte; a run of dropped bytes is reported with the reason seen at its first byte, just before the frame that
 * ends it, or when it reaches {@value AmicaStreamDecoder#BUFFER_SIZE} bytes. What is left at the end (an
 * unfinished run, an incomplete candidate) is not reported. The oracle for {@link AmicaStreamDecoder}.
 */
final class ReferenceScanner {

    private ReferenceScanner() {
    }

    /** @return the events, as {@link RecordingSink} writes them */
    static List<String> scan(byte[] in) {
        List<String> events = new ArrayList<>();
        int run = 0;
        RejectReason runReason = null;
        int i = 0;
        while (in.length - i >= 2) {
            RejectReason reason;
            int size = in[i] & 0xFF;
            if ((in[i + 1] & 0xFF) != AmicaCodec.HEADER_VALUE) {
                reason = RejectReason.BAD_HEADER;
            } else if (in.length - i < AmicaCodec.HEADER_LENGTH) {
                break;
            } else if (size != (in[i + 7] & 0xFF)) {
                reason = RejectReason.LENGTH_MISMATCH;
            } else if (in.length - i < AmicaCodec.HEADER_LENGTH + size) {
                break;
            } else {
                try {
                    AmicaFrame f = AmicaCodec.decode(in, i, AmicaCodec.HEADER_LENGTH + size);
                    if (run > 0) {
                        events.add(runReason + " " + run);
                        run = 0;
                    }
                    events.add(f.toString());
                    i += AmicaCodec.HEADER_LENGTH + size;
                    continue;
                } catch (AmicaProtocolException e) {
                    reason = e.reason();
                }
            }
            if (run == 0) {
                runReason = reason;
            }
            run++;
            i++;
            if (run == AmicaStreamDecoder.BUFFER_SIZE) {
                events.add(runReason + " " + run);
                run = 0;
            }
        }
        return events;
    }
}
