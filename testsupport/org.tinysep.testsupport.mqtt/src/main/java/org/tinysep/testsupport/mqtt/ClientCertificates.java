package org.tinysep.testsupport.mqtt;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Client certificates for a broker that {@link Mosquitto.Builder#requireClientCertificate(boolean) requires one},
 * made with Debian's {@code openssl} inside the test: {@link #issue} one signed by the broker's client CA (the broker
 * accepts it), {@link #selfSigned} one that no CA of the broker signed (the broker refuses it). Both as PKCS12 key
 * stores, the format of the bridge's {@code keyStore}.
 */
public final class ClientCertificates {

    private ClientCertificates() {
    }

    /**
     * @return a PKCS12 key store {@code <folder>/<name>.p12} (password {@code password}) with a new key and its
     *         certificate for {@code CN=name}, signed by the broker's client CA
     */
    public static Path issue(Mosquitto broker, Path folder, String name, String password) throws IOException {
        Path ca = broker.clientCa();
        Files.createDirectories(folder);
        Tools.run(folder, List.of("openssl", "req", "-newkey", "rsa:2048", "-nodes", "-keyout", name + "-key.pem",
                "-out", name + ".csr", "-subj", "/CN=" + name));
        Tools.run(folder, List.of("openssl", "x509", "-req", "-in", name + ".csr", "-CA", ca.toString(),
                "-CAkey", ca.resolveSibling(Certificates.CLIENT_CA_KEY).toString(), "-CAcreateserial",
                "-out", name + "-cert.pem", "-days", "2"));
        return pkcs12(folder, name, password);
    }

    /** @return a PKCS12 key store like {@link #issue}'s, but self-signed: no broker trusts it */
    public static Path selfSigned(Path folder, String name, String password) throws IOException {
        Files.createDirectories(folder);
        Tools.run(folder, List.of("openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes",
                "-keyout", name + "-key.pem", "-out", name + "-cert.pem", "-days", "2", "-subj", "/CN=" + name));
        return pkcs12(folder, name, password);
    }

    private static Path pkcs12(Path folder, String name, String password) throws IOException {
        Tools.run(folder, List.of("openssl", "pkcs12", "-export", "-in", name + "-cert.pem", "-inkey", name + "-key.pem",
                "-name", name, "-out", name + ".p12", "-passout", "pass:" + password));
        return folder.resolve(name + ".p12");
    }
}
