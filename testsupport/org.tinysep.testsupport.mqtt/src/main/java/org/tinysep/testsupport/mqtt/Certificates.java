package org.tinysep.testsupport.mqtt;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * Generates a self-signed server certificate for 127.0.0.1 (openssl, subjectAltName IP:127.0.0.1 so hostname
 * verification passes) and a PKCS12 trust store holding it (keytool); for brokers that require client certificates
 * also a client CA ({@link ClientCertificates} issues the clients' certificates with it).
 */
final class Certificates {

    static final String CERT = "server-cert.pem";
    static final String KEY = "server-key.pem";
    static final String TRUST_STORE = "truststore.p12";
    static final String CLIENT_CA = "client-ca.pem";
    static final String CLIENT_CA_KEY = "client-ca-key.pem";

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

    /** A CA (openssl's default v3_ca extensions) that signs the clients' certificates the broker accepts. */
    static void generateClientCa(Path dir) throws IOException {
        Tools.run(dir, List.of("openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes",
                "-keyout", CLIENT_CA_KEY, "-out", CLIENT_CA, "-days", "2", "-subj", "/CN=TinySEP test client CA"));
    }

    private static String keytool() {
        Path inJdk = Path.of(System.getProperty("java.home"), "bin", "keytool");
        return inJdk.toFile().canExecute() ? inJdk.toString() : "keytool";
    }
}
