package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Properties;

/**
 * The web console's address as {@code etc/org.apache.felix.http.cfg} sets it, for the framework properties: Felix
 * HTTP then binds Jetty at the configured address from its first moment, never at the default port 8080 (which may
 * belong to another program, e.g. a second TinySEP) when the file says otherwise. (Felix HTTP still restarts Jetty
 * once when FileInstall delivers the file, at the same address: it restarts on every configuration update, ~20 ms
 * measured.) Only plain values are taken: a value with {@code ${…}} (FileInstall substitutes those) or a port that is
 * no number is left to FileInstall, and the default stands until then.
 */
final class HttpCfg {

    static final String FILE = "org.apache.felix.http.cfg";
    static final String HOST = "org.apache.felix.http.host";
    static final String PORT = "org.osgi.service.http.port";
    static final String HTTP_ENABLE = "org.apache.felix.http.enable";
    static final String HTTPS_ENABLE = "org.apache.felix.https.enable";

    private HttpCfg() {
    }

    /** @return the host and port the file sets with plain values (none when it is missing or unreadable) */
    static Properties read(Path cfg) {
        Properties out = new Properties();
        Properties file;
        try {
            file = CfgFile.load(cfg);
        } catch (IOException | IllegalArgumentException e) {
            return out; // FileInstall reports a broken file; the defaults stand
        }
        String host = plain(file.getProperty(HOST));
        if (host != null) {
            out.setProperty(HOST, host);
        }
        String port = plain(file.getProperty(PORT));
        if (port != null && port.matches("\\d{1,5}")) {
            out.setProperty(PORT, port);
        }
        return out;
    }

    /**
     * @return whether the console's HTTP service may wait for its first use behind the launcher's socket
     *         ({@link WebOnDemand}): plain HTTP on a loopback address only. With HTTPS, a network address or a value
     *         FileInstall substitutes later the console starts after the banner: a connection the launcher handed
     *         over would reach Jetty at 127.0.0.1, where its plain-HTTP rule would take it for this machine's own
     */
    static boolean onFirstUse(Path cfg) {
        Properties file;
        try {
            file = CfgFile.load(cfg);
        } catch (IOException | IllegalArgumentException e) {
            return false; // FileInstall reports a broken file; the console starts as it says
        }
        String host = file.getProperty(HOST, "127.0.0.1").strip();
        return !Boolean.parseBoolean(file.getProperty(HTTPS_ENABLE, "false").strip())
                && Boolean.parseBoolean(file.getProperty(HTTP_ENABLE, "true").strip())
                && !file.getProperty(PORT, "").contains("${")
                && (host.equals("localhost") || host.equals("::1") || host.matches("127(\\.\\d{1,3}){3}"));
    }

    private static String plain(String value) {
        return value == null || value.isBlank() || value.contains("${") ? null : value.strip();
    }
}
