package org.tinysep.timecontroller.internal;

import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.tinysep.link.sync.SyncSecret;

/**
 * Authentication of the synchroniser's requests (docs/time-sync.md, "Authentication"). Every TICK and BYE carries
 * {@code hex(HMAC-SHA256(key, "<session> <request without the hmac>"))}. A session is a random value the platform
 * gives a sender address at its first HELLO (every later HELLO from it gets the same), kept while the link is open;
 * so a request captured from one synchroniser is worthless from any other address and after a restart. Within a session
 * sequence numbers must increase: a request whose number is not above the last accepted one is refused as
 * {@code replayed}, except the exact resend of the last TICK (a lost DONE). Sessions are bounded: at most
 * {@link #MAX_SESSIONS} that only said HELLO, and apart from them at most {@link #MAX_TRUSTED} that carried an
 * accepted signed request; HELLOs never push out the latter. Thread-safe.
 */
final class SyncAuth {

    /** Why a request is refused: an ERROR code and its text. */
    record Refusal(String code, String text) {
    }

    /** Sessions given by HELLO and not (yet) used for an accepted request, kept at most (least recent goes first). */
    static final int MAX_SESSIONS = 256;
    /**
     * Sessions that carried an accepted, signed request (a synchroniser with the key), kept at most. Only another
     * signed session can push one out: a flood of HELLOs from other ports never evicts the live synchroniser's
     * session.
     */
    static final int MAX_TRUSTED = 16;

    private static final class Session {
        final String value;
        long lastSeq = -1;
        Instant lastAt;

        Session(String value) {
            this.value = value;
        }
    }

    private final byte[] key;
    private final String noKey;
    private final SecureRandom random = new SecureRandom();
    private final Map<InetSocketAddress, Session> sessions = lru(MAX_SESSIONS);
    private final Map<InetSocketAddress, Session> trusted = lru(MAX_TRUSTED);

    private static Map<InetSocketAddress, Session> lru(int max) {
        return new LinkedHashMap<>(16, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<InetSocketAddress, Session> eldest) {
                return size() > max;
            }
        };
    }

    /**
     * @param key   the shared secret, or null when there is none ({@code noKey} says why): every TICK is refused
     * @param noKey the reason there is no key, shown in the refusal
     */
    SyncAuth(byte[] key, String noKey) {
        this.key = key == null ? null : key.clone();
        this.noKey = noKey;
    }

    /** @return the session value of {@code from} (16 hex digits), created at its first HELLO */
    synchronized String hello(InetSocketAddress from) {
        Session known = trusted.get(from);
        if (known != null) {
            return known.value;
        }
        return sessions.computeIfAbsent(from, a -> {
            byte[] s = new byte[8];
            random.nextBytes(s);
            return new Session(HexFormat.of().formatHex(s));
        }).value;
    }

    /** @return null when {@code request} from {@code from} may be carried out, else why not */
    synchronized Refusal check(SyncMessage.Signed request, Instant at, InetSocketAddress from) {
        String command = request.signed().substring(0, request.signed().indexOf(' '));
        if (request.mac() == null) {
            return new Refusal("unauthorized", command + " without an HMAC: send " + request.signed()
                    + " <hex HMAC-SHA256 of '<session> " + request.signed() + "'> (docs/time-sync.md)");
        }
        if (key == null) {
            return new Refusal("unauthorized", "the platform has no synchroniser key (" + noKey + ")");
        }
        Session session = session(from);
        if (session == null) {
            return new Refusal("unauthorized", "no session for " + from.getAddress().getHostAddress() + ":"
                    + from.getPort() + ": send HELLO first and sign with the session of its WELCOME");
        }
        byte[] expected = SyncSecret.hmac(key, session.value, request.signed()).getBytes(StandardCharsets.US_ASCII);
        byte[] given = request.mac().toLowerCase(Locale.ROOT).getBytes(StandardCharsets.US_ASCII);
        if (!MessageDigest.isEqual(expected, given)) {
            return new Refusal("unauthorized", "wrong HMAC: not signed with the platform's synchroniser key for "
                    + "this sender's session (see WELCOME)");
        }
        boolean resend = request.seq() == session.lastSeq && at != null && at.equals(session.lastAt);
        if (request.seq() <= session.lastSeq && !resend) {
            return new Refusal("replayed", "sequence number " + request.seq() + " is not above the last accepted "
                    + session.lastSeq + " of this session");
        }
        return null;
    }

    private Session session(InetSocketAddress from) {
        Session s = trusted.get(from);
        return s != null ? s : sessions.get(from);
    }

    /** Records an authenticated request that was carried out ({@code at}: its instant, null for BYE). */
    synchronized void accepted(InetSocketAddress from, long seq, Instant at) {
        Session session = sessions.remove(from);
        if (session != null) {
            trusted.put(from, session); // signed with the key: no HELLO flood can push it out any more
        } else {
            session = trusted.get(from);
        }
        if (session != null) {
            session.lastSeq = seq;
            session.lastAt = at;
        }
    }
}
