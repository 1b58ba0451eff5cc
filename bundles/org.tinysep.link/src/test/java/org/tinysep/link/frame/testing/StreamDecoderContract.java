package org.tinysep.link.frame.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.link.frame.testing.TestBytes.concat;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.IntSupplier;
import java.util.function.LongSupplier;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.FrameStream;

/**
 * What every protocol family's stream decoder must do, written once: a family's decoder test extends this class,
 * names its sample frames and the few places where the families differ, and keeps only the tests of its own rules.
 */
public abstract class StreamDecoderContract {

    /**
     * A fresh decoder of the family under test, fed and read through its own recording sink.
     *
     * @param events frames as their {@code toString()}, runs as {@code "REASON n"}, in order
     */
    public record Probe(FrameChecks.Accept decoder, IntSupplier buffered, Runnable reset,
            Supplier<List<String>> events, IntSupplier frames, LongSupplier skipped) {
    }

    /** @return a fresh decoder and sink */
    protected abstract Probe fresh();

    /** @return four valid frames; the first without its last byte, then the second, resynchronise at the second */
    protected abstract List<byte[]> samples();

    /** @return what the sink records for a valid frame */
    protected abstract String text(byte[] frame) throws Exception;

    /** @return the i-th of 2,000 valid frames for the buffer tests */
    protected abstract byte[] numbered(int i);

    /** @return the longest frame of the family */
    protected abstract int maxFrame();

    /** @return the index of the checksum byte in the third sample */
    protected abstract int checksumIndex();

    /** @return the reason of a run of zero bytes */
    protected abstract String zeroRunReason();

    /** @return how many bytes of a long run of zeros wait in the buffer, undecided */
    protected abstract int zerosLeftBuffered();

    /** Creates a decoder without a sink (must throw NullPointerException). */
    protected abstract void newWithNullSink();

    /** @return garbage at the start of the split test, chosen by the family to look like a header */
    protected byte[] trickyGarbage() {
        return hex("01 02 03");
    }

    private static void feed(Probe p, byte[] bytes) {
        p.decoder().accept(bytes, 0, bytes.length);
    }

    private List<String> texts(byte[]... frames) throws Exception {
        List<String> out = new ArrayList<>();
        for (byte[] f : frames) {
            out.add(text(f));
        }
        return out;
    }

    private byte[] sample(int i) {
        return samples().get(i);
    }

    private byte[] badChecksum() {
        byte[] bad = sample(2).clone();
        bad[checksumIndex()] ^= 0x40;
        return bad;
    }

    @Test
    void decodesBackToBackFrames() throws Exception {
        Probe p = fresh();
        feed(p, concat(samples().toArray(byte[][]::new)));
        assertEquals(texts(samples().toArray(byte[][]::new)), p.events().get());
        assertEquals(0, p.buffered().getAsInt());
    }

    @Test
    void frameWithBadChecksumIsSkippedAndTheNextFrameDecoded() throws Exception {
        Probe p = fresh();
        feed(p, concat(badChecksum(), sample(2)));
        assertEquals(List.of("BAD_CHECKSUM " + sample(2).length, text(sample(2))), p.events().get());
    }

    @Test
    void frameWithALostByteIsSkippedAndTheNextFrameDecoded() throws Exception {
        Probe p = fresh();
        byte[] lost = Arrays.copyOf(sample(0), sample(0).length - 1);
        feed(p, concat(lost, sample(1)));
        assertEquals(List.of("BAD_CHECKSUM " + lost.length, text(sample(1))), p.events().get());
    }

    @Test
    void sameResultWhenSplitAtEveryPairOfByteBoundaries() throws Exception {
        byte[] stream = concat(trickyGarbage(), sample(0), hex("FF"), sample(1), badChecksum(), sample(2), sample(3));
        Probe p = fresh();
        feed(p, stream);
        List<String> expected = List.copyOf(p.events().get());
        assertEquals(4, p.frames().getAsInt());
        assertFalse(expected.get(0).equals(text(sample(0))), "the garbage is reported first: " + expected);
        assertEquals(text(sample(3)), expected.get(expected.size() - 1));
        FrameChecks.assertSplitsAlike(stream, expected, () -> {
            Probe f = fresh();
            return new FrameChecks.Feeding(f.decoder(), f.events());
        });
    }

    @Test
    void decodesMoreFramesInOneCallThanTheBufferHolds() throws Exception {
        int count = 2000;
        byte[][] frames = new byte[count][];
        for (int i = 0; i < count; i++) {
            frames[i] = numbered(i);
        }
        Probe p = fresh();
        feed(p, concat(frames));
        assertEquals(count, p.frames().getAsInt());
        assertEquals(text(frames[count - 1]), p.events().get().get(count - 1));
        assertEquals(0, p.skipped().getAsLong());
    }

    @Test
    void bufferStaysBoundedUnderEndlessGarbageAndEveryByteIsAccountedFor() throws Exception {
        Probe p = fresh();
        FrameChecks.assertEndlessGarbageStaysBounded(new FrameChecks.Counted(p.decoder(), p.buffered(), p.frames(),
                p.skipped(), () -> p.events().get().size()), maxFrame(), FrameStream.BUFFER_SIZE);
        feed(p, concat(sample(0), new byte[maxFrame()], sample(1)));
        assertTrue(p.frames().getAsInt() >= 1 && p.frames().getAsInt() <= 2, "frames after garbage: " + p.frames().getAsInt());
        List<String> events = p.events().get();
        assertEquals(text(sample(1)), events.get(events.size() - 1), "a frame after garbage is decoded");
    }

    @Test
    void longRunsAreReportedInChunksOfTheBufferSize() throws Exception {
        Probe p = fresh();
        int size = FrameStream.BUFFER_SIZE;
        String reason = zeroRunReason();
        feed(p, new byte[10_000]);
        assertEquals(List.of(reason + " " + size, reason + " " + size), p.events().get());
        assertEquals(zerosLeftBuffered(), p.buffered().getAsInt());
        feed(p, sample(0));
        assertEquals(List.of(reason + " " + size, reason + " " + size, reason + " " + (10_000 - 2 * size),
                text(sample(0))), p.events().get());
    }

    @Test
    void resetReportsAnIncompleteFrameAndStartsAfresh() throws Exception {
        Probe p = fresh();
        int part = sample(3).length - 2;
        feed(p, Arrays.copyOf(sample(3), part));
        assertEquals(part, p.buffered().getAsInt());
        p.reset().run();
        assertEquals(List.of("TRUNCATED " + part), p.events().get());
        assertEquals(0, p.buffered().getAsInt());
        feed(p, sample(0));
        assertEquals(List.of("TRUNCATED " + part, text(sample(0))), p.events().get());
    }

    @Test
    void rejectsRangesOutsideTheInput() {
        Probe p = fresh();
        assertThrows(IndexOutOfBoundsException.class, () -> p.decoder().accept(new byte[4], 2, 3));
        assertThrows(NullPointerException.class, this::newWithNullSink);
    }
}
