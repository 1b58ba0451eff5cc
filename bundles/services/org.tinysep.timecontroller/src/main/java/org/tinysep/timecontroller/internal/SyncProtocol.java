package org.tinysep.timecontroller.internal;

import java.net.InetSocketAddress;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.ClockMode;
import org.tinysep.device.support.intake.RejectSampler;
import org.tinysep.device.support.intake.SourceGate;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * The platform side of the synchroniser protocol: one datagram in, one answer out. TICK and BYE must be signed
 * ({@link SyncAuth}). Rejections are counted per code; the first of each code goes to the event log (a PROBLEM),
 * every rejected datagram to the packet log.
 */
final class SyncProtocol implements SyncLink.Handler {

    /** The clock being driven (the Time Controller device). */
    interface Target {
        Instant now();

        ClockMode mode();

        /** Applies a tick; on ADVANCED every listener has run when this returns. */
        SyncClock.TickResult tick(long seq, Instant at);
    }

    static final List<String> CODES = List.of("malformed", "unknown-command", "too-long", "backwards", "not-external",
            "unauthorized", "replayed", "forbidden");

    private final DriverContext context;
    private final Target target;
    private final SyncAuth auth;
    private final Runnable bye;
    private final SourceGate gate;
    private final RejectSampler sampler;
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong ticks = new AtomicLong();
    private final Map<String, AtomicLong> rejected = new LinkedHashMap<>();

    /** @param bye what an authenticated {@code BYE} does: the clock returns to REAL time */
    SyncProtocol(DriverContext context, Target target, SyncAuth auth, Runnable bye) {
        this(context, target, auth, bye, SourceGate.of("127.0.0.1", "", 0));
    }

    /** @param gate who may send at all: a sender off its allow-list is refused before anything else */
    SyncProtocol(DriverContext context, Target target, SyncAuth auth, Runnable bye, SourceGate gate) {
        this.context = context;
        this.gate = gate;
        this.sampler = new RejectSampler(context.reporter(), context.driverUid());
        this.target = target;
        this.auth = auth;
        this.bye = bye;
        CODES.forEach(c -> rejected.put(c, new AtomicLong()));
    }

    @Override
    public String datagram(byte[] data, int length, InetSocketAddress from) {
        received.incrementAndGet();
        if (gate.check(from.getAddress()) != SourceGate.Verdict.PASS) {
            return reject("forbidden", SyncMessage.error("-", "forbidden", from.getAddress().getHostAddress()
                    + " is not an allowed time synchroniser (syncAllowedSources)"),
                    Arrays.copyOf(data, Math.min(length, data.length)), from);
        }
        SyncMessage message;
        try {
            message = SyncMessage.parse(data, length);
        } catch (SyncMessage.Invalid e) {
            return reject(e.code(), e.answer(), Arrays.copyOf(data, Math.min(length, data.length)), from);
        }
        if (message instanceof SyncMessage.Signed signed) {
            SyncAuth.Refusal refusal = auth.check(signed, signed instanceof SyncMessage.Tick t ? t.at() : null,
                    from);
            if (refusal != null) {
                return reject(refusal.code(), SyncMessage.error(Long.toString(signed.seq()), refusal.code(),
                        refusal.text()), Arrays.copyOf(data, length), from);
            }
        }
        if (message instanceof SyncMessage.Bye b) {
            auth.accepted(from, b.seq(), null);
            bye.run();
            return SyncMessage.done(b.seq(), target.now());
        }
        if (message instanceof SyncMessage.Tick tick) {
            SyncClock.TickResult r = target.tick(tick.seq(), tick.at());
            return switch (r.outcome()) {
                case ADVANCED, REPEATED -> {
                    auth.accepted(from, tick.seq(), tick.at());
                    ticks.incrementAndGet();
                    yield SyncMessage.done(tick.seq(), r.now());
                }
                case BACKWARDS -> reject("backwards", SyncMessage.error(Long.toString(tick.seq()), "backwards",
                        tick.at() + " is before the current time " + r.now()), Arrays.copyOf(data, length), from);
                case NOT_EXTERNAL -> reject("not-external", SyncMessage.error(Long.toString(tick.seq()),
                        "not-external", "the clock is in REAL mode; switch it to EXTERNAL first"),
                        Arrays.copyOf(data, length), from);
            };
        }
        return SyncMessage.welcome(target.now(), target.mode(), auth.hello(from));
    }

    private String reject(String code, String answer, byte[] datagram, InetSocketAddress from) {
        String sender = from.getAddress().getHostAddress() + ":" + from.getPort();
        sampler.rejected(context.driverUid(), datagram, "rejected from " + sender + ": " + answer);
        if (rejected.get(code).incrementAndGet() == 1) {
            context.event(EventKind.PROBLEM, "rejected time sync datagram from " + sender + ": " + answer
                    + "; further '" + code + "' rejections are only counted");
        }
        return answer;
    }

    long received() {
        return received.get();
    }

    long ticks() {
        return ticks.get();
    }

    long rejected(String code) {
        return rejected.get(code).get();
    }

    /** @return {@code received}, {@code ticks}, {@code rejected} and {@code rejected.<code>} */
    List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("received", received.get(), "synchroniser datagrams received"));
        out.add(Parameter.readOnly("ticks", ticks.get(), "TICKs answered with DONE"));
        out.add(Parameter.readOnly("rejected", rejected.values().stream().mapToLong(AtomicLong::get).sum(),
                "datagrams answered with ERROR"));
        rejected.forEach((code, n) -> out.add(Parameter.readOnly("rejected." + code, n.get(),
                "ERROR answers with code " + code)));
        return out;
    }
}
