package org.tinysep.device.support.intake;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * The decoder path both bus radios share, on a toy family: a frame is one byte, 0 is rejected with the reason
 * {@code ZERO}, 9 makes the decoder fail with a bug (not a rejection).
 */
class PacketIntakeTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    enum Reason { ZERO, SKIPPED }

    static final class ToyException extends Exception {
        private static final long serialVersionUID = 1L;

        ToyException(String message) {
            super(message);
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final List<String> counted = new ArrayList<>();
    private final List<String> handled = new ArrayList<>();
    private final PacketIntake<Integer, Reason, ToyException, String> intake = new PacketIntake<>(
            new DriverContext(null, "driver-uid", "Toy", logs.reporter(), new PlatformClock(() -> T0)),
            new PacketIntake.Codec<>(PacketIntakeTest::decode, ToyException.class, e -> Reason.ZERO),
            (reason, message, origin) -> counted.add(reason + " " + message + " from " + origin)) {

        @Override
        protected String origin(String from) {
            return "toy " + from;
        }

        @Override
        protected void handle(Integer frame, byte[] raw, String from, Instant at) {
            handled.add(frame + " from " + from + (at == null ? "" : " at " + at));
        }
    };

    private static Integer decode(byte[] raw) throws ToyException {
        if (raw.length != 1 || raw[0] == 0) {
            throw new ToyException("ZERO (no frame)");
        }
        if (raw[0] == 9) {
            throw new IllegalStateException("decoder bug");
        }
        return (int) raw[0];
    }

    @Test
    void aDatagramIsCopiedDecodedAndHandedOnOrCountedAndSampledUnderItsReason() {
        byte[] buffer = {5, 0, 0};
        intake.datagram(buffer, 1, "a");
        buffer[0] = 0;
        intake.datagram(buffer, 1, "b", T0);
        intake.datagram(new byte[] {7}, 1, "c", T0);

        assertEquals(List.of("5 from a", "7 from c at " + T0), handled);
        assertEquals(List.of("ZERO ZERO (no frame) from toy b"), counted);
        List<PacketEntry> packets = logs.packets();
        assertEquals(1, packets.size(), "only the rejected datagram is logged here: the family logs valid ones");
        assertEquals("toy b", packets.get(0).origin());
        assertArrayEquals(new byte[] {0}, packets.get(0).bytes(), "the bytes of this datagram, copied");
        assertEquals(3, intake.received());
    }

    @Test
    void aDecoderBugIsNotARejection() {
        assertThrows(IllegalStateException.class, () -> intake.datagram(new byte[] {9}, 1, "a"));
        assertEquals(List.of(), counted);
    }

    @Test
    void framesRejectedRunsRefusalsAndRefusedSourcesAreCountedAsTheirKindIs() {
        intake.frame(4, new byte[] {4}, "serial");
        intake.rejected(Reason.SKIPPED, "SKIPPED: 3 bytes", new byte[0], "serial");
        intake.refused(new ToyException("ZERO (empty radiogram)"), new byte[0], "sdk");
        intake.refused("not on the allow-list", new byte[] {1, 2, 3}, 2, "udp");

        assertEquals(List.of("4 from serial"), handled);
        assertEquals(List.of("SKIPPED SKIPPED: 3 bytes from toy serial", "ZERO ZERO (empty radiogram) from toy sdk"),
                counted);
        assertEquals(List.of("toy serial", "toy sdk", "toy udp"),
                logs.packets().stream().map(PacketEntry::origin).toList());
        assertArrayEquals(new byte[] {1, 2}, logs.packets().get(2).bytes());
        assertEquals(3, intake.received(), "a stream's skipped run is not a packet handed in");
    }
}
