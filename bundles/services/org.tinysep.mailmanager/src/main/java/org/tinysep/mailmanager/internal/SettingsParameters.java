package org.tinysep.mailmanager.internal;

import java.util.List;
import org.tinysep.api.device.Parameter;

/** The configuration as read-only device parameters; the password is never shown ({@code ***} when set). */
final class SettingsParameters {

    private SettingsParameters() {
    }

    static List<Parameter> of(MailSettings s) {
        String cfg = "set through ConfigAdmin pid " + MailManagerDriver.PID;
        return List.of(
                Parameter.readOnly("host", s.host(), cfg),
                Parameter.readOnly("port", s.port(), cfg),
                Parameter.readOnly("security", s.security(), cfg),
                Parameter.readOnly("user", s.user(), cfg),
                Parameter.readOnly("password", s.password().isEmpty() ? "" : MailSettings.MASK, cfg
                        + " (deprecated: plain text in the framework cache; use passwordFile)"),
                Parameter.readOnly("passwordFile", SmtpPassword.describe(s), cfg
                        + "; the password file, its state (owner-only, missing, readable by others)"),
                Parameter.readOnly("giveUpAfterSeconds", s.giveUpAfterSeconds(), cfg),
                Parameter.readOnly("from", s.from(), cfg),
                Parameter.readOnly("recipients", String.join(", ", s.recipients()), cfg),
                Parameter.readOnly("spoolDir", s.spoolDir(), cfg),
                Parameter.readOnly("trustedCertificates", s.trustedCertificates() == null ? "(the Java runtime's)"
                        : s.trustedCertificates(), cfg + "; the certificates trusted for TLS and STARTTLS"));
    }
}
