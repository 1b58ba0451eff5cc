package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * The key of the signed JSON messages ({@link org.tinysep.json.JsonSignature}, docs/mqtt.md, "Signed messages"):
 * read from its file, in plain words when it is missing or too short.
 */
final class Signatures {

    /** The shortest key accepted, in characters. */
    static final int MIN_KEY = 16;

    private Signatures() {
    }

    /**
     * @return the key: the first line of the file, at least {@value #MIN_KEY} characters
     * @throws IOException in plain words: missing, unreadable or too short
     */
    static byte[] key(Path file) throws IOException {
        String k = Secrets.firstLine(file, "MQTT key").strip();
        if (k.length() < MIN_KEY) {
            throw new IOException("the MQTT key file " + file + " holds " + k.length() + " characters, at least "
                    + MIN_KEY + " are needed (e.g. openssl rand -hex 32)");
        }
        return k.getBytes(StandardCharsets.UTF_8);
    }
}
