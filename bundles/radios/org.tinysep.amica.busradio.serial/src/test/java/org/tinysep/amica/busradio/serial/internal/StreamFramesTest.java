package org.tinysep.amica.busradio.serial.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.serial.internal.Wiring.concat;
import static org.tinysep.amica.busradio.serial.internal.Wiring.frame;
import static org.tinysep.amica.busradio.serial.internal.Wiring.keepAlive;

import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaStreamDecoder;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.device.support.intake.RejectCounter;

/** Bytes of a serial stream, cut anywhere, become frames and skipped runs, each logged with its exact bytes. */
class StreamFramesTest {

    private final Wiring wiring = new Wiring("BusRadioAmicaSerial /dev/test");
    private final Wiring.Parts<String> parts = wiring.parts();
    private final RejectCounter<RejectReason> rejects = parts.rejects();
    private final StreamFrames<String> frames = new StreamFrames<>(parts.handler(), "/dev/test");

    @Test
    void garbageBetweenFramesIsSkippedAsOneRunAndEveryByteIsInThePacketLogOnce() {
        byte[] keepAlive = frame(1, 17, 0, keepAlive(AmicaNodeType.MOVEMENT));
        byte[] garbage = {0, 1, 2, 3, (byte) 0xFF, 0x55};
        byte[] motion = frame(1, 17, 1, new MotionDetection(true));
        byte[] badChecksum = motion.clone();
        badChecksum[6] ^= 1;
        byte[] stream = concat(keepAlive, garbage, motion, badChecksum, motion);

        Random random = new Random(42);
        for (int off = 0; off < stream.length; ) { // cut the stream at random places, like serial reads do
            int n = Math.min(stream.length - off, 1 + random.nextInt(9));
            frames.accept(Arrays.copyOfRange(stream, off, off + n), n);
            off += n;
        }

        List<PacketEntry> packets = wiring.logs.packets();
        assertEquals(5, packets.size(), packets.toString());
        assertArrayEquals(keepAlive, packets.get(0).bytes());
        assertArrayEquals(garbage, packets.get(1).bytes());
        assertEquals("BAD_HEADER (header value is not 0xA1 (AmICA node protocol v1)): 6 bytes skipped",
                packets.get(1).note());
        assertEquals("/dev/test", packets.get(1).origin());
        assertArrayEquals(motion, packets.get(2).bytes());
        assertArrayEquals(badChecksum, packets.get(3).bytes(), "a bad frame is skipped as one run of its bytes");
        assertTrue(packets.get(3).note().startsWith("BAD_CHECKSUM"), packets.get(3).note());
        assertArrayEquals(motion, packets.get(4).bytes());
        assertEquals(1, rejects.count(RejectReason.BAD_HEADER));
        assertEquals(1, rejects.count(RejectReason.BAD_CHECKSUM));
        assertEquals(garbage.length + badChecksum.length, frames.skippedBytes());
        assertEquals(3, Long.parseLong(parts.nodes().find(new AmicaAddress(1, 17)).parameters().stream()
                .filter(p -> p.key().equals("packets")).findFirst().orElseThrow().value()));
        assertEquals(0, frames.pending());
    }

    @Test
    void endlessGarbageStaysBoundedAndIsReportedInRuns() {
        byte[] noise = new byte[3 * AmicaStreamDecoder.BUFFER_SIZE + 100];
        Arrays.fill(noise, (byte) 0x42);
        frames.accept(noise, noise.length);
        assertTrue(frames.pending() <= AmicaStreamDecoder.BUFFER_SIZE, "pending " + frames.pending());
        assertEquals(3 * AmicaStreamDecoder.BUFFER_SIZE, frames.skippedBytes());

        byte[] keepAlive = frame(1, 17, 0, keepAlive(AmicaNodeType.MOVEMENT));
        frames.accept(keepAlive, keepAlive.length);
        assertEquals(3 * AmicaStreamDecoder.BUFFER_SIZE + 100, frames.skippedBytes());
        List<PacketEntry> packets = wiring.logs.packets();
        assertArrayEquals(keepAlive, packets.get(packets.size() - 1).bytes(), "the frame after the noise is found");
        assertEquals(4, rejects.count(RejectReason.BAD_HEADER));
    }

    @Test
    void resetDropsAPartialFrameAsTruncated() {
        byte[] keepAlive = frame(1, 17, 0, keepAlive(AmicaNodeType.MOVEMENT));
        frames.accept(keepAlive, 10);
        frames.reset();
        assertEquals(1, rejects.count(RejectReason.TRUNCATED));
        assertArrayEquals(Arrays.copyOf(keepAlive, 10), wiring.logs.packets().get(0).bytes());

        frames.accept(keepAlive, keepAlive.length); // the rest of the old frame is gone: a fresh frame decodes
        assertArrayEquals(keepAlive, wiring.logs.packets().get(1).bytes());
        assertEquals("", wiring.logs.packets().get(1).note());
    }
}
