package org.tinysep.device.support.intake;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;
import org.tinysep.api.device.Parameter;

/**
 * Who may send to a UDP link (docs/security.md). On a link bound to a loopback address every sender is accepted
 * (only local programs can reach it). On any other bind address (e.g. {@code 0.0.0.0}) only sources on the
 * allow-list are accepted (default: {@code 127.0.0.1} and {@code ::1}), and each allowed source IP may send at
 * most {@code perSecond} datagrams per second (a token bucket holding one second's worth), so a flooding sender
 * cannot starve the others. Refusals are counted exactly. Thread-safe.
 */
public final class SourceGate {

    /** What the gate says about one datagram. */
    public enum Verdict { PASS, NOT_ALLOWED, RATE_LIMITED }

    /** Most source IPs with a rate bucket at once; the least recently seen one is forgotten beyond. */
    static final int MAX_SOURCES = 4096;
    private static final List<String> DEFAULT_ALLOWED = List.of("127.0.0.1", "::1");

    private final boolean enforced;
    private final List<Cidr> allowed;
    private final int perSecond;
    private final LongSupplier nanos;
    private final Map<InetAddress, Bucket> buckets = new LinkedHashMap<>(16, 0.75f, true);
    private final AtomicLong notAllowed = new AtomicLong();
    private final AtomicLong rateLimited = new AtomicLong();

    private SourceGate(boolean enforced, List<Cidr> allowed, int perSecond, LongSupplier nanos) {
        this.enforced = enforced;
        this.allowed = allowed;
        this.perSecond = perSecond;
        this.nanos = nanos;
    }

    /**
     * @param bindAddress   the link's local address; a loopback one turns the gate off
     * @param allowList     comma- or space-separated addresses or CIDR blocks ({@code 192.168.1.20},
     *                      {@code 10.0.0.0/24}); empty = {@code 127.0.0.1, ::1}
     * @param perSecond     datagrams per second per source IP; 0 or less = no limit
     * @throws IllegalArgumentException naming the entry that is not an address or block
     */
    public static SourceGate of(String bindAddress, String allowList, int perSecond) {
        return of(bindAddress, allowList, perSecond, System::nanoTime);
    }

    static SourceGate of(String bindAddress, String allowList, int perSecond, LongSupplier nanos) {
        boolean loopback;
        try {
            loopback = InetAddress.getByName(bindAddress.strip()).isLoopbackAddress();
        } catch (UnknownHostException e) {
            loopback = false; // the link will not bind anyway; be strict
        }
        List<String> entries = allowList == null || allowList.isBlank() ? DEFAULT_ALLOWED
                : List.of(allowList.strip().split("[,\\s]+"));
        List<Cidr> cidrs = new ArrayList<>();
        for (String e : entries) {
            cidrs.add(Cidr.parse(e));
        }
        return new SourceGate(!loopback, List.copyOf(cidrs), perSecond, nanos);
    }

    /** @return the verdict for one datagram from {@code source}; counts a refusal */
    public Verdict check(InetAddress source) {
        if (!enforced) {
            return Verdict.PASS;
        }
        if (allowed.stream().noneMatch(c -> c.contains(source))) {
            notAllowed.incrementAndGet();
            return Verdict.NOT_ALLOWED;
        }
        if (perSecond > 0 && !take(source)) {
            rateLimited.incrementAndGet();
            return Verdict.RATE_LIMITED;
        }
        return Verdict.PASS;
    }

    private synchronized boolean take(InetAddress source) {
        long now = nanos.getAsLong();
        Bucket b = buckets.get(source);
        if (b == null) {
            if (buckets.size() >= MAX_SOURCES) {
                InetAddress eldest = buckets.keySet().iterator().next();
                buckets.remove(eldest);
            }
            b = new Bucket(perSecond, now);
            buckets.put(source, b);
        }
        b.tokens = Math.min(perSecond, b.tokens + (now - b.at) * perSecond / 1e9);
        b.at = now;
        if (b.tokens < 1) {
            return false;
        }
        b.tokens -= 1;
        return true;
    }

    /** @return the packet-log note of a refusal, e.g. "rejected: source 127.0.0.2 is not on the allow-list" */
    public static String why(Verdict verdict, InetAddress source) {
        return "rejected: source " + source.getHostAddress() + (verdict == Verdict.NOT_ALLOWED
                ? " is not on the allow-list" : " sends faster than the per-source rate limit");
    }

    /**
     * @return the event-log text of the first refusal of its kind (just counted by {@link #check}), else null: later
     *         ones are only counted
     */
    public String firstRefusal(Verdict verdict, InetAddress source) {
        long n = verdict == Verdict.NOT_ALLOWED ? notAllowed.get() : verdict == Verdict.RATE_LIMITED
                ? rateLimited.get() : 0;
        if (n != 1) {
            return null;
        }
        return why(verdict, source) + " (" + describe() + "); further " + verdict + " rejections are only counted";
    }

    /** @return whether the allow-list and rate limit apply (the link is not bound to loopback) */
    public boolean enforced() {
        return enforced;
    }

    public long notAllowed() {
        return notAllowed.get();
    }

    public long rateLimited() {
        return rateLimited.get();
    }

    /** @return e.g. "allow-list 127.0.0.1, ::1; at most 2000 datagrams/s per source" or "loopback: ..." */
    public String describe() {
        if (!enforced) {
            return "bound to loopback: every local sender accepted";
        }
        return "allow-list " + String.join(", ", allowed.stream().map(Cidr::toString).toList())
                + (perSecond > 0 ? "; at most " + perSecond + " datagrams/s per source" : "; no rate limit");
    }

    /** @return {@code sources}, {@code rejected.source_not_allowed}, {@code rejected.rate_limited} */
    public List<Parameter> parameters() {
        return List.of(Parameter.readOnly("sources", describe(), "who may send (docs/security.md)"),
                Parameter.readOnly("rejected.source_not_allowed", notAllowed.get(),
                        "datagrams from a source not on the allow-list"),
                Parameter.readOnly("rejected.rate_limited", rateLimited.get(),
                        "datagrams over the per-source rate limit"));
    }

    private static final class Bucket {
        double tokens;
        long at;

        Bucket(double tokens, long at) {
            this.tokens = tokens;
            this.at = at;
        }
    }

    /** An address or a block {@code address/prefix}. */
    record Cidr(byte[] network, int prefix, String text) {

        static Cidr parse(String entry) {
            String e = entry.strip();
            int slash = e.indexOf('/');
            String host = slash < 0 ? e : e.substring(0, slash);
            if (!host.matches("[0-9a-fA-F:.]+")) { // addresses only: no name lookups for an allow-list
                throw new IllegalArgumentException("allow-list entry '" + e + "' is not an IP address or block");
            }
            try {
                byte[] net = InetAddress.getByName(host).getAddress();
                int prefix = slash < 0 ? net.length * 8 : Integer.parseInt(e.substring(slash + 1));
                if (prefix < 0 || prefix > net.length * 8) {
                    throw new IllegalArgumentException("allow-list entry '" + e + "': prefix out of range");
                }
                return new Cidr(net, prefix, e);
            } catch (UnknownHostException | NumberFormatException ex) {
                throw new IllegalArgumentException("allow-list entry '" + e + "' is not an IP address or block");
            }
        }

        boolean contains(InetAddress address) {
            byte[] a = address.getAddress();
            if (a.length != network.length) {
                return false;
            }
            int full = prefix / 8;
            for (int i = 0; i < full; i++) {
                if (a[i] != network[i]) {
                    return false;
                }
            }
            int rest = prefix % 8;
            if (rest == 0) {
                return true;
            }
            int mask = (0xFF << (8 - rest)) & 0xFF;
            return (a[full] & mask) == (network[full] & mask);
        }

        @Override
        public String toString() {
            return text;
        }
    }
}
