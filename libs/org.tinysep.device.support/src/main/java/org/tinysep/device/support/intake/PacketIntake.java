package org.tinysep.device.support.intake;

import java.time.Instant;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * The decoder path every link of a bus radio feeds, written once for both node families: counts what is
 * handed in, copies a datagram (the transport may reuse its buffer), decodes it with the family's {@link Codec} and
 * hands on the frame ({@link #handle}); rejected input is counted under its reason by the family's {@link Counter}
 * and goes to the packet log through one {@link RejectSampler}, like refused sources and the summary of what was not
 * kept. A family's handler (the AmICA {@code FrameHandler}, the Sun SPOT {@code PacketHandler}) adds only its node
 * table and what a valid frame becomes. Links may call it on their own receive threads; the subclass's
 * {@code handle} must allow that.
 *
 * @param <F> the family's frame
 * @param <R> the family's reject reason
 * @param <X> the family's protocol exception, the one its codec throws
 * @param <S> where input comes from: a route, or a link's description
 */
public abstract class PacketIntake<F, R, X extends Exception, S> {

    /**
     * A family's datagram decoder, e.g. {@code raw -> AmicaCodec.decode(raw, 0, raw.length)}.
     *
     * @param <F> the frame
     * @param <X> the protocol exception
     */
    @FunctionalInterface
    public interface Decoder<F, X extends Exception> {
        F decode(byte[] raw) throws X;
    }

    /**
     * How a family decodes a datagram and names why it failed; one constant per family.
     *
     * @param decoder  decodes one datagram
     * @param failure  the class of the decoder's protocol exception
     * @param reasonOf the exception's reason, e.g. {@code e -> e.reason()}
     */
    public record Codec<F, R, X extends Exception>(Decoder<F, X> decoder, Class<X> failure, Function<X, R> reasonOf) {
    }

    /**
     * Counts one rejection under its reason, e.g. a bus radio's reject counter ({@code rejects::reject}).
     *
     * @param <R> the reject reason
     */
    @FunctionalInterface
    public interface Counter<R> {
        /**
         * @param message the reason and detail in the form of the family's exception message
         * @param origin  where the input came from, e.g. {@code 127.0.0.1:5000}
         */
        void reject(R reason, String message, String origin);
    }

    private final DriverContext context;
    private final Codec<F, R, X> codec;
    private final Counter<R> counter;
    private final RejectSampler sampler;
    private final AtomicLong received = new AtomicLong();

    protected PacketIntake(DriverContext context, Codec<F, R, X> codec, Counter<R> counter) {
        this.context = context;
        this.codec = codec;
        this.counter = counter;
        this.sampler = new RejectSampler(context.reporter(), context.driverUid());
    }

    /** Handles bytes that must be exactly one frame, such as a UDP datagram; {@code data} may be reused after. */
    public final void datagram(byte[] data, int length, S from) {
        datagram(data, length, from, null);
    }

    /**
     * Like {@link #datagram(byte[], int, Object)}, stamped {@code at} instead of the platform time now (a transport
     * that takes a late frame during a platform tick stamps it with the time it arrived in).
     *
     * @param at the platform time of the frame; {@code null} for now
     */
    public final void datagram(byte[] data, int length, S from, Instant at) {
        received.incrementAndGet();
        byte[] raw = Arrays.copyOf(data, length);
        F frame;
        try {
            frame = codec.decoder().decode(raw);
        } catch (Exception e) {
            if (!codec.failure().isInstance(e)) {
                throw (RuntimeException) e; // the decoder declares only X
            }
            rejectFor(codec.failure().cast(e), raw, from);
            return;
        }
        handle(frame, raw, from, at);
    }

    /**
     * Handles a frame whose framing was checked already: found in a byte stream, or built from an SDK radiogram.
     *
     * @param raw the bytes as they arrived, for the packet log
     */
    public final void frame(F frame, byte[] raw, S from) {
        received.incrementAndGet();
        handle(frame, raw, from, null);
    }

    /** Handles input a link refused before it became a frame (e.g. an empty radiogram): counted and rejected. */
    public final void refused(X failure, byte[] raw, S from) {
        received.incrementAndGet();
        rejectFor(failure, raw, from);
    }

    /**
     * Records input that a link's framing already rejected, e.g. a run of bytes a stream decoder skipped: counted
     * under its reason and written to the packet log.
     *
     * @param message the reason and detail in the form of the family's exception message
     */
    public final void rejected(R reason, String message, byte[] raw, S from) {
        reject(reason, message, raw, from);
    }

    /**
     * Records a datagram the transport refused for its source (not on the allow-list, over the rate limit; the
     * transport's {@code SourceGate} counts it): in the packet log, sampled like every rejected input.
     */
    public final void refused(String why, byte[] data, int length, S from) {
        received.incrementAndGet();
        sampler.rejected(origin(from), Arrays.copyOf(data, length), why);
    }

    /** Writes the summary of rejected input not kept in the packet log, at most once a minute; call on a tick. */
    public final void flushRejects() {
        sampler.flush();
    }

    /** @return how many datagrams or frames were handed in, rejected ones included (stream runs not) */
    public final long received() {
        return received.get();
    }

    protected final DriverContext context() {
        return context;
    }

    /** Counts rejected input under its reason and puts it into the packet log while the sampler's budget lasts. */
    protected final void reject(R reason, String message, byte[] raw, S from) {
        String origin = origin(from);
        counter.reject(reason, message, origin);
        sampler.rejected(origin, raw, message);
    }

    /** Puts input into the packet log as rejected while the sampler's budget lasts, not counted under a reason. */
    protected final void sample(String origin, byte[] raw, String note) {
        sampler.rejected(origin, raw, note);
    }

    /** @return where input from {@code from} came from, for logs, e.g. {@code 127.0.0.1:5000} */
    protected abstract String origin(S from);

    /**
     * Delivers a decoded frame.
     *
     * @param at the platform time of the frame; {@code null} for now
     */
    protected abstract void handle(F frame, byte[] raw, S from, Instant at);

    private void rejectFor(X failure, byte[] raw, S from) {
        reject(codec.reasonOf().apply(failure), failure.getMessage(), raw, from);
    }
}
