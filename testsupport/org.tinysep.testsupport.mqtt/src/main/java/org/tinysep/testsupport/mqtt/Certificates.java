package org.tinysep.testsupport.mqtt;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * Generates a self-signed server certificate for 127.0.0.1 (openssl, subjectAltName IP:127.0.0.1 so hostname
 * verification passes) and a PKCS12 trust store holding it (keytool).
 */
final class Certificates {

    static final String CERT = "server-cert.pem";
    static final String KEY = "server-key.pem";
    static final String TRUST_STORE = "truststore.p12";

    private Certificates() {
    }

    static void generate(Path dir) throws IOException {
        Tools.run(dir, List.of("openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes",
                "-keyout", KEY, "-out", CERT, "-days", "2", "-subj", "/CN=127.0.0.1",
                "-addext", "subjectAltName=IP:127.0.0.1,DNS:localhost"));
        Tools.run(dir, List.of(keytool(), "-importcert", "-noprompt", "-alias", "mosquitto-test",
                "-file", CERT, "-keystore", TRUST_STORE, "-storetype", "PKCS12",
                "-storepass", Mosquitto.TRUST_STORE_PASSWORD));
    }

    private static String keytool() {
        Path inJdk = Path.of(System.getProperty("java.home"), "bin", "keytool");
        return inJdk.toFile().canExecute() ? inJdk.toString() : "keytool";
    }
}
