package org.tinysep.json;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.link.sync.SyncSecret;

/**
 * The signature of a JSON message on a topic (docs/mqtt.md, "Signed messages"), with the HMAC the time synchroniser
 * signs its requests with ({@link SyncSecret#hmacHex}): {@code sig} = lower-case hex HMAC-SHA256(key, topic + "\n" +
 * the JSON object without {@code sig}, as UTF-8), written as the object's last field. The exact bytes are signed: no
 * canonical form, a receiver strips the trailing {@code ,"sig":"…"} and checks the rest. The topic is signed too, so a message cannot be moved to another topic
 * (an alert's message is no command, flat A's no message of flat B). Written once for the MQTT bridge, which signs
 * its messages and checks commands, and the care centre's board, which checks the flats' messages and signs its
 * acknowledgements; each has its own key files, read with {@link #readKey}.
 */
public final class JsonSignature {

    /** The shortest key {@link #readKey} accepts, in characters. */
    public static final int MIN_KEY = 16;

    private static final Pattern SIGNED = Pattern.compile("(?s)(\\{.*?),?\"sig\":\"([0-9a-f]{64})\"\\}");

    /** What a check found: the signed object without {@code sig} when {@link #valid}. */
    public record Checked(boolean signed, boolean valid, String unsigned) {
    }

    private JsonSignature() {
    }

    /** @return the JSON object {@code json} with its {@code sig} as last field */
    public static String sign(byte[] key, String topic, String json) {
        String body = json.strip();
        body = body.substring(0, body.length() - 1).stripTrailing();
        return body + (body.endsWith("{") ? "" : ",") + "\"sig\":\"" + mac(key, topic, body + "}") + "\"}";
    }

    /**
     * @param key null when the sender's key is unknown: a signed text is then never valid
     * @return whether {@code text} carries a {@code sig} and whether it is right for {@code topic} and {@code key}
     */
    public static Checked check(byte[] key, String topic, String text) {
        Matcher m = SIGNED.matcher(text.strip());
        if (!m.matches()) {
            return new Checked(false, false, text);
        }
        String unsigned = m.group(1).stripTrailing() + "}";
        if (key == null) {
            return new Checked(true, false, unsigned);
        }
        boolean ok = MessageDigest.isEqual(mac(key, topic, unsigned).getBytes(StandardCharsets.US_ASCII),
                m.group(2).getBytes(StandardCharsets.US_ASCII));
        return new Checked(true, ok, unsigned);
    }

    /**
     * Reads a signing key: the first line of {@code file} without surrounding white space, at least {@value #MIN_KEY}
     * characters, as UTF-8 bytes.
     *
     * @param what names the file in messages, e.g. {@code "MQTT key"}
     * @throws IOException in plain words: the file is missing or unreadable, or its key too short
     */
    public static byte[] readKey(Path file, String what) throws IOException {
        if (file == null || !Files.isRegularFile(file)) {
            throw new IOException("the " + what + " file " + file + " does not exist");
        }
        String k = Files.readString(file, StandardCharsets.UTF_8).lines().findFirst().orElse("").strip();
        if (k.length() < MIN_KEY) {
            throw new IOException("the " + what + " file " + file + " holds " + k.length() + " characters, at least "
                    + MIN_KEY + " are needed (e.g. openssl rand -hex 32)");
        }
        return k.getBytes(StandardCharsets.UTF_8);
    }

    /** @return the lower-case hex HMAC-SHA256 of {@code topic + "\n" + json} */
    public static String mac(byte[] key, String topic, String json) {
        return SyncSecret.hmacHex(key, (topic + "\n" + json).getBytes(StandardCharsets.UTF_8));
    }
}
