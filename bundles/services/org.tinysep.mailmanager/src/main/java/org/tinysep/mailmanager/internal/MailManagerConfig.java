package org.tinysep.mailmanager.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.AttributeType;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/**
 * Configuration of the Mail Manager (pid {@value MailManagerDriver#PID}). The component reads the raw values
 * through {@link MailSettings#parse} so that a bad value gets a clear message instead of a conversion error.
 */
@ObjectClassDefinition(name = "TinySEP Mail Manager", description = "Sends e-mail alerts through SMTP.")
public @interface MailManagerConfig {

    @AttributeDefinition(description = "SMTP server host name; empty = not configured: mail is written to the log")
    String host() default "";

    @AttributeDefinition(description = "SMTP server port (587 submission with STARTTLS, 465 TLS, 25 plain)")
    int port() default MailSettings.DEFAULT_PORT;

    @AttributeDefinition(description = "Connection security: NONE, STARTTLS (required) or TLS (implicit, smtps)")
    String security() default "STARTTLS";

    @AttributeDefinition(description = "SMTP user name; empty = no authentication")
    String user() default "";

    @AttributeDefinition(description = "SMTP password file (first line), owner-only; empty = "
            + "${tinysep.var}/secrets/smtp.password. Kept out of backups")
    String passwordFile() default "";

    @AttributeDefinition(description = "Deprecated: SMTP password in the configuration, stored in plain text in the "
            + "framework cache; use passwordFile. Wins over the file when set (never logged, shown as ***)",
            type = AttributeType.PASSWORD)
    String password() default "";

    @AttributeDefinition(description = "Sender address (From:)")
    String from() default "";

    @AttributeDefinition(description = "Recipient addresses, comma-separated")
    String recipients() default "";

    @AttributeDefinition(description = "Connect and read time limit in seconds")
    int connectTimeoutSeconds() default MailSettings.DEFAULT_CONNECT_TIMEOUT;

    @AttributeDefinition(description = "First retry delay in seconds after a failed attempt; doubled per failure")
    int retryInitialSeconds() default MailSettings.DEFAULT_RETRY_INITIAL;

    @AttributeDefinition(description = "Longest retry delay in seconds")
    int retryMaxSeconds() default MailSettings.DEFAULT_RETRY_MAX;

    @AttributeDefinition(description = "Give a message up when it has failed temporarily for this many seconds "
            + "(default 86400 = 24 h)")
    int giveUpAfterSeconds() default MailSettings.DEFAULT_GIVE_UP_AFTER;

    @AttributeDefinition(description = "Spool folder for queued mail; empty = ${tinysep.var}/mail-spool, else "
            + "${tinysep.home}/var/mail-spool, else mail-spool in the working directory")
    String spoolDir() default "";

    @AttributeDefinition(description = "PEM file of the certificates to trust for TLS and STARTTLS instead of the "
            + "Java runtime's (a server with its own, self-signed certificate); empty = the Java runtime's trust store")
    String trustedCertificates() default "";
}
