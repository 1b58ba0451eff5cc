package org.tinysep.testsupport.mqtt;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.HexFormat;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * Signs MQTT messages as docs/mqtt.md ("Signed messages") says, written here a second time on purpose: a test that
 * signs with this and is accepted by the bridge or the board checks the wire format, not the same code twice.
 * {@code sig} = hex HMAC-SHA256(key, topic + "\n" + the JSON object without sig), the object's last field.
 */
public final class Signed {

    private static final SecureRandom RANDOM = new SecureRandom();

    private Signed() {
    }

    /** @return {@code json} (a compact JSON object) with {@code "sig"} appended as its last field */
    public static String sign(String key, String topic, String json) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key.getBytes(StandardCharsets.UTF_8), "HmacSHA256"));
            String sig = HexFormat.of().formatHex(mac.doFinal((topic + "\n" + json).getBytes(StandardCharsets.UTF_8)));
            String body = json.substring(0, json.length() - 1);
            return body + (body.endsWith("{") ? "" : ",") + "\"sig\":\"" + sig + "\"}";
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * @param fields the command's fields without the braces, e.g. {@code "by":"Eva"}
     * @return a signed command: the fields, {@code at} = now, a new {@code nonce}, {@code sig}
     */
    public static String command(String key, String topic, String fields) {
        return sign(key, topic, commandBody(fields, Instant.now()));
    }

    /** @return the unsigned command object with {@code at} and a new {@code nonce} */
    public static String commandBody(String fields, Instant at) {
        byte[] n = new byte[8];
        RANDOM.nextBytes(n);
        return "{" + fields + ",\"at\":\"" + at + "\",\"nonce\":\"" + HexFormat.of().formatHex(n) + "\"}";
    }
}
