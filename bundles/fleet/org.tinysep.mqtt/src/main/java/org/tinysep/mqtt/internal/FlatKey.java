package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.nio.file.Path;
import org.tinysep.json.JsonSignature;

/**
 * The flat's key ({@code keyFile}), read once when the bridge starts: it signs the flat's JSON messages (so the care
 * centre's board knows they come from this flat) and checks signed commands.
 *
 * @param key     the key, null when there is none
 * @param missing why there is none (plain words), else null
 * @param warning a warning when others may read the file, else null
 */
record FlatKey(byte[] key, String missing, String warning) {

    static FlatKey read(Path file) {
        try {
            byte[] k = JsonSignature.readKey(file, "MQTT key");
            String open = Secrets.openToOthers(file);
            return new FlatKey(k, null, open == null ? null : open.replace("password file", "MQTT key file"));
        } catch (IOException e) {
            return new FlatKey(null, e.getMessage(), null);
        }
    }
}
