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
import java.util.function.Function;
import java.util.function.IntFunction;
import java.util.function.IntSupplier;
import java.util.function.LongSupplier;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.FrameStream;

/**
 * What every protocol family's stream decoder must do, written once: a family's decoder test extends this class,
 * describes its decoder and sample frames in one {@link Family} and keeps only the tests of its own rules, which
 * use the decoder and sink made for each test ({@link #decoder}, {@link #sink}, {@link #feed}, {@link #text}).
 *
 * @param <F> the frame
 * @param <R> the reject reason
 * @param <S> the family's recording sink
 */
public abstract class StreamDecoderContract<F, R, S extends Recording<F, R>> {

    /**
     * What the contract needs of a family.
     *
     * @param sinks             makes the family's recording sink
     * @param decoders          makes the family's stream decoder with a sink (null must throw NullPointerException)
     * @param codec             the family's frame codec's {@code decode}
     * @param samples           four valid frames; the first without its last byte, then the second, resynchronise
     *                          at the second
     * @param numbered          the i-th of 2,000 valid frames for the buffer tests
     * @param maxFrame          the longest frame of the family
     * @param checksumIndex     the index of the checksum byte in the third sample
     * @param zeroRunReason     the reason of a run of zero bytes
     * @param zerosLeftBuffered how many bytes of a long run of zeros wait in the buffer, undecided
     * @param trickyGarbage     garbage at the start of the split test, chosen by the family to look like a header
     * @param garbageReason     the reason of the garbage {@code FF 00 13} before the first sample
     * @param resets            the family's garbage for the reset tests
     */
    public record Family<F, R, S extends Recording<F, R>>(Supplier<S> sinks, Function<S, FrameStream<F, R>> decoders,
            Codecs.FrameDecoder<F> codec, List<byte[]> samples, IntFunction<byte[]> numbered, int maxFrame,
            int checksumIndex, String zeroRunReason, int zerosLeftBuffered, byte[] trickyGarbage, String garbageReason,
            Resets resets) {
    }

    /**
     * The family's garbage for the reset tests.
     *
     * @param pending       garbage the decoder drops, then keeps dropping with the first 5 bytes of the first sample
     * @param pendingReason the reason of that run
     * @param pendingWaits  how many of those bytes wait in the buffer before the reset
     * @param longRun       {@link FrameStream#BUFFER_SIZE} - 1 bytes the decoder drops
     * @param longReason    the reason of that run
     * @param tail          an incomplete valid frame after the long run
     */
    public record Resets(byte[] pending, String pendingReason, int pendingWaits, byte[] longRun, String longReason,
            byte[] tail) {
    }

    /**
     * A fresh decoder of the family under test, fed and read through its own recording sink.
     *
     * @param events frames as their {@code toString()}, runs as {@code "REASON n"}, in order
     */
    public record Probe(FrameChecks.Accept decoder, IntSupplier buffered, Runnable reset,
            Supplier<List<String>> events, IntSupplier frames, LongSupplier skipped) {
    }

    private final Family<F, R, S> family;
    /** This test's sink. */
    protected final S sink;
    /** This test's decoder, reporting to {@link #sink}. */
    protected final FrameStream<F, R> decoder;

    protected StreamDecoderContract(Family<F, R, S> family) {
        this.family = family;
        this.sink = family.sinks().get();
        this.decoder = family.decoders().apply(sink);
    }

    /** Feeds {@code bytes} to this test's decoder in one call. */
    protected final void feed(byte[] bytes) {
        decoder.accept(bytes, 0, bytes.length);
    }

    /** @return what the sink records for a valid frame */
    protected final String text(byte[] frame) throws Exception {
        return family.codec().decode(frame, 0, frame.length).toString();
    }

    /** @return a fresh decoder and sink */
    private Probe fresh() {
        S r = family.sinks().get();
        FrameStream<F, R> d = family.decoders().apply(r);
        return new Probe(d::accept, d::buffered, d::reset, () -> r.events, () -> r.frames, () -> r.skipped);
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
        return family.samples().get(i);
    }

    private byte[] badChecksum() {
        byte[] bad = sample(2).clone();
        bad[family.checksumIndex()] ^= 0x40;
        return bad;
    }

    @Test
    void skipsGarbageBeforeAFrameAndReportsItOnce() throws Exception {
        Probe p = fresh();
        feed(p, concat(hex("FF 00 13"), sample(0)));
        assertEquals(List.of(family.garbageReason() + " 3", text(sample(0))), p.events().get());
    }

    @Test
    void decodesBackToBackFrames() throws Exception {
        Probe p = fresh();
        feed(p, concat(family.samples().toArray(byte[][]::new)));
        assertEquals(texts(family.samples().toArray(byte[][]::new)), p.events().get());
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
        byte[] stream =
                concat(family.trickyGarbage(), sample(0), hex("FF"), sample(1), badChecksum(), sample(2), sample(3));
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
            frames[i] = family.numbered().apply(i);
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
                p.skipped(), () -> p.events().get().size()), family.maxFrame(), FrameStream.BUFFER_SIZE);
        feed(p, concat(sample(0), new byte[family.maxFrame()], sample(1)));
        assertTrue(p.frames().getAsInt() >= 1 && p.frames().getAsInt() <= 2, "frames after garbage: " + p.frames().getAsInt());
        List<String> events = p.events().get();
        assertEquals(text(sample(1)), events.get(events.size() - 1), "a frame after garbage is decoded");
    }

    @Test
    void longRunsAreReportedInChunksOfTheBufferSize() throws Exception {
        Probe p = fresh();
        int size = FrameStream.BUFFER_SIZE;
        String reason = family.zeroRunReason();
        feed(p, new byte[10_000]);
        assertEquals(List.of(reason + " " + size, reason + " " + size), p.events().get());
        assertEquals(family.zerosLeftBuffered(), p.buffered().getAsInt());
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
    void resetReportsPendingGarbageAndIncompleteFrameAsOneRun() {
        Resets x = family.resets();
        Probe p = fresh();
        feed(p, concat(x.pending(), Arrays.copyOf(sample(0), 5)));
        assertEquals(x.pendingWaits(), p.buffered().getAsInt());
        assertEquals(List.of(), p.events().get(), "a run is reported when it ends");
        p.reset().run();
        assertEquals(List.of(x.pendingReason() + " " + (x.pending().length + 5)), p.events().get());
        p.reset().run();
        assertEquals(1, p.events().get().size(), "nothing left to report");
    }

    @Test
    void resetReportsARunLongerThanTheBufferInChunksOfTheBufferSize() {
        Resets x = family.resets();
        assertEquals(FrameStream.BUFFER_SIZE - 1, x.longRun().length, "one short of a reported chunk");
        Probe p = fresh();
        feed(p, concat(x.longRun(), x.tail()));
        assertEquals(List.of(), p.events().get());
        assertEquals(x.tail().length, p.buffered().getAsInt());
        p.reset().run();
        // the run with its reason up to the bound, then the rest of the candidate as a truncated frame
        assertEquals(List.of(x.longReason() + " " + FrameStream.BUFFER_SIZE, "TRUNCATED " + (x.tail().length - 1)),
                p.events().get());
        assertEquals(0, p.buffered().getAsInt());
        p.reset().run();
        assertEquals(2, p.events().get().size(), "nothing left to report");
    }

    @Test
    void rejectsRangesOutsideTheInput() {
        Probe p = fresh();
        assertThrows(IndexOutOfBoundsException.class, () -> p.decoder().accept(new byte[4], 2, 3));
        assertThrows(NullPointerException.class, () -> family.decoders().apply(null));
    }
}
