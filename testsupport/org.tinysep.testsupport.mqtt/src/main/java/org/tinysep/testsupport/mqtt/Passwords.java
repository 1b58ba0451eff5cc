package org.tinysep.testsupport.mqtt;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** Writes a mosquitto password file with {@code mosquitto_passwd -b -c}. */
final class Passwords {

    private Passwords() {
    }

    static void write(Path file, String user, String password) throws IOException {
        Files.deleteIfExists(file);
        Tools.run(file.getParent(), List.of(passwdBinary(), "-c", "-b", file.toString(), user, password));
    }

    private static String passwdBinary() {
        for (String candidate : List.of("/usr/bin/mosquitto_passwd", "/usr/local/bin/mosquitto_passwd")) {
            if (Files.isExecutable(Path.of(candidate))) {
                return candidate;
            }
        }
        return "mosquitto_passwd";
    }
}
