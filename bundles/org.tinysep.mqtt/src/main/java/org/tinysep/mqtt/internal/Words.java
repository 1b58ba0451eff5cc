package org.tinysep.mqtt.internal;

import java.net.ConnectException;
import java.net.SocketTimeoutException;
import java.net.UnknownHostException;
import javax.net.ssl.SSLException;
import org.eclipse.paho.mqttv5.common.MqttException;

/** Connection trouble in plain words, for the bridge device's status and one log line (never a stack trace). */
final class Words {

    private Words() {
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

    static String describe(Throwable e) {
        Throwable root = e;
        while (root.getCause() != null && root.getCause() != root) {
            root = root.getCause();
        }
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
            return "TLS failed: " + root.getMessage() + " (is the broker's certificate in the trust store?)";
        }
        String msg = root.getMessage() != null ? root.getMessage() : e.getMessage();
        return msg != null ? msg : root.getClass().getSimpleName();
    }
}
