package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.EventKind;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * Issue 10, item 6 (password part): the SMTP password comes from an owner-only file kept out of the configuration
 * (and so out of the framework cache and backups); a password in the configuration still works, with a warning.
 */
class PasswordFileTest {

    private static final String SECRET = "Very-Secret-42";

    @TempDir
    Path dir;

    private final MailHarness h = new MailHarness();
    private final SmtpSink server = new SmtpSink().requireLogin("alice", SECRET);

    @AfterEach
    void tearDown() {
        h.close();
        server.close();
    }

    private Map<String, Object> withLogin() throws Exception {
        int port = server.start().port();
        Map<String, Object> config = MailHarness.smtp(port, dir.resolve("spool"));
        config.put("user", "alice");
        config.put("passwordFile", dir.resolve("secrets/smtp.password").toString());
        return config;
    }

    private Path writePassword(String perms) throws Exception {
        Path f = Files.createDirectories(dir.resolve("secrets")).resolve("smtp.password");
        Files.writeString(f, SECRET + "\n");
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString(perms));
        return f;
    }

    @Test
    void passwordFromAnOwnerOnlyFileLogsInWithoutWarnings() throws Exception {
        Map<String, Object> config = withLogin();
        writePassword("rw-------");
        MailManagerDevice device = h.start(config);

        device.provider().send("alert", "body");

        MailHarness.await("delivered with the file's password", () -> server.recipients().size() == 2);
        assertTrue(h.logs.events().stream().noneMatch(e -> e.kind() == EventKind.PROBLEM), h.eventTexts().toString());
        assertTrue(device.parameters().stream().anyMatch(p -> p.key().equals("passwordFile")
                && p.value().endsWith("smtp.password (owner-only)")));
        assertSecretNowhere(device);
    }

    @Test
    void aFileOthersCanReadIsUsedButWarnedAboutPlainly() throws Exception {
        Map<String, Object> config = withLogin();
        Path f = writePassword("rw-r--r--");
        MailManagerDevice device = h.start(config);

        MailHarness.await("warned", () -> h.logs.events().stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().equals("the SMTP password file " + f + " can be read by other users of this computer "
                        + "(mode rw-r--r--); make it owner-only: chmod 600 " + f)));
        assertTrue(h.stderr().contains("can be read by other users"), "a WARN line too");
        device.provider().send("alert", "body");
        MailHarness.await("still delivered", () -> server.recipients().size() == 2);
        assertSecretNowhere(device);
    }

    @Test
    void aPasswordInTheConfigurationStillWorksWithAWarning() throws Exception {
        Map<String, Object> config = withLogin();
        config.put("password", SECRET);
        MailManagerDevice device = h.start(config);

        MailHarness.await("warned", () -> h.eventTexts().stream().anyMatch(e -> e.startsWith("the SMTP password is "
                + "set with the key 'password' of configuration org.tinysep.mailmanager: it is stored in plain text "
                + "in the framework cache")));
        device.provider().send("alert", "body");
        MailHarness.await("delivered", () -> server.recipients().size() == 2);
        assertSecretNowhere(device);
    }

    @Test
    void aMissingFileIsSaidPlainlyAndTheAlertWaits() throws Exception {
        Map<String, Object> config = withLogin();
        MailManagerDevice device = h.start(config);

        device.provider().send("alert", "body");
        MailHarness.await("said", () -> h.eventTexts().stream().anyMatch(e -> e.startsWith("SMTP user 'alice' is set "
                + "but the password file ") && e.endsWith("does not exist: the server will refuse the login until it "
                + "is written")));
        MailHarness.await("retrying", () -> device.status().detail().contains("the server refused the login"));
        writePassword("rw-------");
        device.invoke("retryNow");
        MailHarness.await("delivered once the file is there (read at each attempt)",
                () -> server.recipients().size() == 2);
    }

    private void assertSecretNowhere(MailManagerDevice device) {
        assertFalse(h.stderr().contains(SECRET), "SLF4J output");
        assertTrue(h.eventTexts().stream().noneMatch(e -> e.contains(SECRET)), "event log");
        assertTrue(device.parameters().stream().noneMatch(p -> p.value().contains(SECRET)), "parameters");
        assertFalse(device.status().toString().contains(SECRET), "status");
        assertEquals(-1, device.health().summary().indexOf(SECRET));
    }
}
