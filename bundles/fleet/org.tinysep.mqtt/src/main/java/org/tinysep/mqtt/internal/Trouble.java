package org.tinysep.mqtt.internal;

import java.net.ConnectException;
import java.net.SocketTimeoutException;
import java.net.UnknownHostException;
import javax.net.ssl.SSLException;
import org.eclipse.paho.mqttv5.common.MqttException;

/** Connection trouble in plain words, for the bridge device's status and one log line (never a stack trace). */
final class Trouble {

    /** TLS alerts a broker sends about the client's certificate (received fatal alert: …). */
    private static final java.util.List<String> CLIENT_CERTIFICATE_ALERTS = java.util.List.of("unknown_ca",
            "bad_certificate", "certificate_unknown", "unsupported_certificate", "certificate_expired",
            "certificate_revoked", "access_denied");

    private Trouble() {
    }

    /** @return whether the broker refused us (login, authorisation, client id): retrying will not help */
    static boolean refused(Throwable e) {
        if (e instanceof MqttException m) {
            int c = m.getReasonCode();
            return c == 133 || c == 134 || c == 135 || c == 138 || c == 140 || c == 4 || c == 5;
        }
        return false;
    }

    static String connectFailure(Throwable e) {
        if (e instanceof MqttException m) {
            switch (m.getReasonCode()) {
                case 134, 4:
                    return "the broker refused the login: bad user name or password";
                case 135, 5:
                    // Mosquitto 2 answers a wrong password with "not authorised" too
                    return "the broker refused the login: wrong user name or password, or this user may not connect";
                case 133:
                    return "the broker refused the client id (the flat id)";
                case 138:
                    return "the broker banned this client";
                default:
                    break;
            }
        }
        return "broker unreachable: " + describe(e);
    }

    /** @return whether Paho's failure may hide a TLS refusal that {@link TlsProbe} can name */
    static boolean mayHideTlsAlert(Throwable e) {
        Throwable root = root(e);
        return !(root instanceof ConnectException || root instanceof UnknownHostException
                || root instanceof SocketTimeoutException) && !(e instanceof MqttException m && refused(m));
    }

    /** @return whether a TLS failure's message is the broker's alert about the client certificate */
    static boolean aboutClientCertificate(String message) {
        return message.contains("certificate_required") || CLIENT_CERTIFICATE_ALERTS.stream().anyMatch(message::contains);
    }

    /** A TLS failure in words: which side refused what, and what to check. */
    static String tls(String message) {
        if (message.contains("certificate_required")) {
            return "TLS failed: the broker requires a client certificate (" + message
                    + "; set keyStore and keyStorePasswordFile)";
        }
        for (String alert : CLIENT_CERTIFICATE_ALERTS) {
            if (message.contains(alert)) {
                return "TLS failed: the broker refused this flat's client certificate (" + message
                        + "; is it signed by a CA the broker trusts, and still valid?)";
            }
        }
        return "TLS failed: " + message + " (is the broker's certificate in the trust store?)";
    }

    private static Throwable root(Throwable e) {
        Throwable root = e;
        while (root.getCause() != null && root.getCause() != root) {
            root = root.getCause();
        }
        return root;
    }

    static String describe(Throwable e) {
        Throwable root = root(e);
        if (root instanceof ConnectException) {
            return "connection refused (is the broker running, is the address right?)";
        }
        if (root instanceof UnknownHostException) {
            return "unknown host " + root.getMessage();
        }
        if (root instanceof SocketTimeoutException) {
            return "no answer within the timeout";
        }
        if (root instanceof SSLException || root instanceof java.security.cert.CertificateException) {
            return tls(String.valueOf(root.getMessage()));
        }
        String msg = root.getMessage() != null ? root.getMessage() : e.getMessage();
        return msg != null ? msg : root.getClass().getSimpleName();
    }
}
