package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Configuration parsing: defaults, validation with clear messages, no password in any text. */
class MailSettingsTest {

    private static Map<String, Object> valid() {
        Map<String, Object> c = new HashMap<>();
        c.put("host", "smtp.example.org");
        c.put("from", "home@example.org");
        c.put("recipients", " a@example.org ,b@example.org,");
        c.put("user", "home");
        c.put("password", "pw-123");
        return c;
    }

    @Test
    void defaults() {
        MailSettings s = MailSettings.parse(valid(), "/opt/tinysep");
        assertEquals(587, s.port());
        assertEquals(Security.STARTTLS, s.security());
        assertEquals(List.of("a@example.org", "b@example.org"), s.recipients());
        assertEquals(10, s.connectTimeoutSeconds());
        assertEquals(5, s.retryInitialSeconds());
        assertEquals(600, s.retryMaxSeconds());
        assertEquals(86400, s.giveUpAfterSeconds(), "24 h");
        assertEquals(Path.of("/opt/tinysep/var/secrets/smtp.password"), s.passwordFile());
        assertEquals(Path.of("/srv/v/secrets/smtp.password"), MailSettings.parse(Map.of(), "/srv/v", null).passwordFile());
        assertEquals(Path.of("/opt/tinysep/var/mail-spool"), s.spoolDir());
        assertEquals(Path.of("mail-spool").toAbsolutePath(), MailSettings.parse(Map.of(), null).spoolDir());
        assertFalse(MailSettings.parse(Map.of(), null).configured());
        assertFalse(s.toString().contains("pw-123"));
    }

    @Test
    void spoolLivesInTheStateFolderFirst() {
        assertEquals(Path.of("/srv/tinysep-var/mail-spool"),
                MailSettings.parse(Map.of(), "/srv/tinysep-var", "/opt/tinysep").spoolDir());
        assertEquals(Path.of("/opt/tinysep/var/mail-spool"), MailSettings.parse(Map.of(), null, "/opt/tinysep").spoolDir());
        assertEquals(Path.of("/q"), MailSettings.parse(Map.of("spoolDir", "/q"), "/srv/tinysep-var", "/opt/tinysep").spoolDir());
    }

    @Test
    void badValuesGetClearMessages() {
        assertEquals("port must be a whole number, was 'abc'", problem("port", "abc"));
        assertEquals("port must be between 1 and 65535, was 70000", problem("port", 70000));
        assertEquals("security must be NONE, STARTTLS or TLS, was 'SSLv3'", problem("security", "SSLv3"));
        assertEquals("recipients: 'bob' is not an e-mail address", problem("recipients", "a@example.org, bob"));
        assertEquals("recipients must name at least one address (comma-separated)", problem("recipients", " , "));
        assertEquals("from must be one e-mail address like alerts@example.org, was 'home'", problem("from", "home"));
        assertEquals("retryMaxSeconds (3) must not be below retryInitialSeconds (5)", problem("retryMaxSeconds", 3));
        assertEquals("giveUpAfterSeconds must be between 1 and 2592000, was 0", problem("giveUpAfterSeconds", 0));
        assertEquals("host must be a host name or address without port or scheme, was 'smtp://x'",
                problem("host", "smtp://x"));
    }

    private static String problem(String key, Object value) {
        Map<String, Object> c = valid();
        c.put(key, value);
        return assertThrows(IllegalArgumentException.class, () -> MailSettings.parse(c, null)).getMessage();
    }
}
