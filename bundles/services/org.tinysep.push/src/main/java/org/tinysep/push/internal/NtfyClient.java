package org.tinysep.push.internal;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.net.ssl.HttpsURLConnection;
import javax.net.ssl.SSLException;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.device.support.files.TrustedCertificates;

/**
 * ntfy's HTTP publish as JSON (https://docs.ntfy.sh/publish/#publish-as-json): one POST to the server's root with
 * topic, title, message and priority; the token, if any, as a bearer token. TLS only; the server's name is checked
 * against its certificate (HttpsURLConnection's default host name check); a server with its own certificate is
 * trusted through {@link TrustedCertificates}. Blocks at most twice the timeout: called on the channel's own threads.
 */
final class NtfyClient {

    private static final Pattern ID = Pattern.compile("\"id\"\\s*:\\s*\"([^\"]*)\"");

    private NtfyClient() {
    }

    static ChannelDelivery publish(PushSettings s, String topic, ChannelMessage m) {
        if (s.server() == null) {
            return ChannelDelivery.failed(s.problem());
        }
        String json = "{\"topic\":" + quote(topic) + ",\"title\":" + quote(m.title()) + ",\"message\":"
                + quote(m.text()) + ",\"priority\":" + s.priority() + ",\"tags\":[\"rotating_light\"]}";
        String where = "the push server " + s.server().getHost();
        try {
            HttpsURLConnection c = (HttpsURLConnection) s.server().toURL().openConnection();
            if (s.trusted() != null) {
                c.setSSLSocketFactory(TrustedCertificates.factory(s.trusted()));
            }
            c.setConnectTimeout(s.timeoutSeconds() * 1000);
            c.setReadTimeout(s.timeoutSeconds() * 1000);
            c.setRequestMethod("POST");
            c.setDoOutput(true);
            c.setRequestProperty("Content-Type", "application/json");
            String token = PushToken.read(s.tokenFile());
            if (!token.isEmpty()) {
                c.setRequestProperty("Authorization", "Bearer " + token);
            }
            byte[] body = json.getBytes(StandardCharsets.US_ASCII);
            c.setFixedLengthStreamingMode(body.length);
            try (OutputStream out = c.getOutputStream()) {
                out.write(body);
            }
            int code = c.getResponseCode();
            String answer = read(code < 400 ? c.getInputStream() : c.getErrorStream());
            c.disconnect();
            if (code / 100 != 2) {
                return ChannelDelivery.failed(where + " refused it: HTTP " + code + (code == 401 || code == 403
                        ? " (the token in " + s.tokenFile() + " is missing or not allowed to publish to " + topic + ")"
                        : "") + " " + answer.strip());
            }
            Matcher id = ID.matcher(answer);
            return new ChannelDelivery(id.find() ? id.group(1) : "push", MailDelivery.Outcome.SENT, "taken by " + where
                    + " for topic " + topic);
        } catch (SSLException e) {
            return ChannelDelivery.failed(where + " is not trusted (TLS: " + e.getMessage() + "); set "
                    + "trustedCertificates to its certificate if it has its own");
        } catch (IOException | GeneralSecurityException | RuntimeException e) {
            return ChannelDelivery.failed(where + " could not be reached (" + e + ")");
        }
    }

    /** @return {@code s} as a JSON string, non-ASCII as \\u escapes */
    static String quote(String s) {
        StringBuilder b = new StringBuilder("\"");
        for (char ch : s.toCharArray()) {
            switch (ch) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> b.append(ch < 0x20 || ch > 0x7e ? String.format("\\u%04x", (int) ch) : String.valueOf(ch));
            }
        }
        return b.append('"').toString();
    }

    private static String read(InputStream in) throws IOException {
        if (in == null) {
            return "";
        }
        try (in) {
            byte[] b = in.readNBytes(400);
            return new String(b, StandardCharsets.UTF_8);
        }
    }
}
