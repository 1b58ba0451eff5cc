package org.tinysep.web.api.internal;

import java.net.Inet6Address;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.Optional;

/**
 * Rate limit on failed logins, built so that a flood from other addresses cannot lock the right
 * user out:
 * <ul>
 * <li>per address: after {@code maxFailures} failures within {@code window} from one client address (an IPv6
 * client by its /64 network) that address is refused, for every account, until the window has passed;</li>
 * <li>per account and address: once an account has {@code 4 × maxFailures} failures within the window from all
 * addresses together (someone is guessing its password from many places), an address that has failed on that
 * account within the window is refused for that account until its failure has passed the window. An address
 * without failures is never refused because of other addresses: the right password from it logs in;</li>
 * <li>all together: {@code 4 × maxFailures} failures within the window from all addresses is a flood, reported
 * once ({@link #failed} returns its description; again only after {@value #QUIET_WINDOWS} quiet windows).</li>
 * </ul>
 * A successful login clears its address's failures on that account (not the address's count: a guesser who knows
 * one password does not earn more guesses for the other).
 */
public final class LoginLimiter {

    /** Why and how long a client must wait. */
    public record Wait(Duration duration, String reason) {
        static final Wait NONE = new Wait(Duration.ZERO, "");

        public boolean refused() {
            return !duration.isZero() && !duration.isNegative();
        }
    }

    static final int QUIET_WINDOWS = 10;
    private static final String ALL = "*";

    private final int maxFailures;
    private final int floodFailures;
    private final Duration window;
    private final Clock clock;
    private final FailureCounts counts;
    private long total;
    private Instant floodReported;
    private Instant floodLastSeen;

    public LoginLimiter(int maxFailures, Duration window, Clock clock) {
        this.maxFailures = Math.max(1, maxFailures);
        this.floodFailures = this.maxFailures * 4;
        this.window = window;
        this.clock = clock;
        this.counts = new FailureCounts(window, floodFailures);
    }

    /** @return how long {@code client} must wait before trying to log in as {@code account} again */
    public Wait waitFor(String client, String account) {
        Instant now = clock.instant();
        String address = address(client);
        Duration own = counts.waitBelow("a:" + address, maxFailures, now);
        if (!own.isZero()) {
            return new Wait(own, "too many failed logins from your address");
        }
        if (counts.count("u:" + account, now) >= floodFailures) {
            Duration pair = counts.waitBelow("p:" + address + "|" + account, 1, now);
            if (!pair.isZero()) {
                return new Wait(pair, "many failed logins as " + account + " from several addresses, yours among them");
            }
        }
        return Wait.NONE;
    }

    /**
     * Counts one failed login of {@code client} as {@code account}.
     *
     * @return the description of a flood of failed logins, once when it starts (for a PROBLEM entry)
     */
    public synchronized Optional<String> failed(String client, String account) {
        Instant now = clock.instant();
        String address = address(client);
        for (String key : new String[] {"a:" + address, "p:" + address + "|" + account, "u:" + account, ALL}) {
            counts.add(key, now, k -> k.startsWith("a:") || k.startsWith("p:"));
        }
        total++;
        if (counts.count(ALL, now) < floodFailures) {
            return Optional.empty();
        }
        boolean quietSince = floodLastSeen == null
                || !floodLastSeen.plus(window.multipliedBy(QUIET_WINDOWS)).isAfter(now);
        floodLastSeen = now;
        if (floodReported != null && !quietSince) {
            return Optional.empty();
        }
        floodReported = now;
        return Optional.of(floodFailures + " or more failed web console logins within " + window.toSeconds()
                + " s, from " + counts.keysWithFailures("a:", now) + " address(es), the latest from " + client
                + " as '" + account + "' (" + total + " failed logins since the console started). Each such address"
                + " is slowed down; a user at another address can still log in. If nobody you know is trying"
                + " passwords, someone who can reach the console is guessing: keep it on this machine or the home"
                + " network only, and use long passwords (tinysep:web-password)");
    }

    /** Forgets the failures of {@code client} as {@code account} after a successful login. */
    public void succeeded(String client, String account) {
        counts.forget("p:" + address(client) + "|" + account);
    }

    /** @return the failed logins counted since the start */
    public synchronized long total() {
        return total;
    }

    /** @return the address a client is counted under: itself, or for IPv6 its /64 network (one host has many) */
    static String address(String client) {
        if (client == null || client.indexOf(':') < 0 || !client.matches("[0-9A-Fa-f:.%a-zA-Z_]+")) {
            return String.valueOf(client);
        }
        try {
            InetAddress a = InetAddress.getByName(client);
            if (a instanceof Inet6Address && !a.isLoopbackAddress()) {
                byte[] b = a.getAddress();
                StringBuilder prefix = new StringBuilder();
                for (int i = 0; i < 8; i += 2) {
                    prefix.append(Integer.toHexString(((b[i] & 0xff) << 8) | (b[i + 1] & 0xff))).append(':');
                }
                return prefix.append(":/64").toString();
            }
            return a.getHostAddress();
        } catch (UnknownHostException | SecurityException e) { // a literal address never needs a lookup
            return client;
        }
    }
}
