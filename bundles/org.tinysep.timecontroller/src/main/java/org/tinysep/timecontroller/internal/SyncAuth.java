package org.tinysep.timecontroller.internal;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.HexFormat;
import java.util.Locale;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * Authentication of the synchroniser's requests (docs/time-sync.md, "Authentication"). Every TICK and BYE carries
 * {@code hex(HMAC-SHA256(key, "<session> <request without the hmac>"))}; the session is a random value of this link,
 * told in WELCOME, so a request captured before a restart is worthless after it. Within a session sequence numbers
 * must increase: a request whose number is not above the last accepted one is refused as {@code replayed}, except
 * the exact resend of the last TICK (a lost DONE). Thread-safe.
 */
final class SyncAuth {

    /** Why a request is refused: an ERROR code and its text. */
    record Refusal(String code, String text) {
    }

    private final byte[] key;
    private final String noKey;
    private final String session;
    private long lastSeq = -1;
    private Instant lastAt;

    /**
     * @param key   the shared secret, or null when there is none ({@code noKey} says why): every TICK is refused
     * @param noKey the reason there is no key, shown in the refusal
     */
    SyncAuth(byte[] key, String noKey) {
        this.key = key == null ? null : key.clone();
        this.noKey = noKey;
        byte[] s = new byte[8];
        new SecureRandom().nextBytes(s);
        this.session = HexFormat.of().formatHex(s);
    }

    /** The random session value of this link, sent in WELCOME. */
    String session() {
        return session;
    }

    /** @return the lower-case hex HMAC-SHA256 of {@code "<session> <signed>"} with {@code key} */
    static String mac(byte[] key, String session, String signed) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
            return HexFormat.of().formatHex(mac.doFinal((session + " " + signed).getBytes(StandardCharsets.US_ASCII)));
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is part of every Java platform", e);
        }
    }

    /** @return null when {@code request} may be carried out, else why not */
    synchronized Refusal check(SyncMessage.Signed request, Instant at) {
        String command = request.signed().substring(0, request.signed().indexOf(' '));
        if (request.mac() == null) {
            return new Refusal("unauthorized", command + " without an HMAC: send " + request.signed()
                    + " <hex HMAC-SHA256 of '<session> " + request.signed() + "'> (docs/time-sync.md)");
        }
        if (key == null) {
            return new Refusal("unauthorized", "the platform has no synchroniser key (" + noKey + ")");
        }
        byte[] expected = mac(key, session, request.signed()).getBytes(StandardCharsets.US_ASCII);
        byte[] given = request.mac().toLowerCase(Locale.ROOT).getBytes(StandardCharsets.US_ASCII);
        if (!MessageDigest.isEqual(expected, given)) {
            return new Refusal("unauthorized", "wrong HMAC: not signed with the platform's synchroniser key for "
                    + "session " + session + " (see WELCOME)");
        }
        boolean resend = request.seq() == lastSeq && at != null && at.equals(lastAt);
        if (request.seq() <= lastSeq && !resend) {
            return new Refusal("replayed", "sequence number " + request.seq() + " is not above the last accepted "
                    + lastSeq + " of this session");
        }
        return null;
    }

    /** Records an authenticated request that was carried out ({@code at}: its instant, null for BYE). */
    synchronized void accepted(long seq, Instant at) {
        lastSeq = seq;
        lastAt = at;
    }
}
