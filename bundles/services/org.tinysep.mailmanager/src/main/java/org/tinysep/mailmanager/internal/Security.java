package org.tinysep.mailmanager.internal;

/** Connection security towards the SMTP server. */
enum Security {
    /** Plain SMTP, no encryption (a local relay or tests only). */
    NONE,
    /** SMTP upgraded with STARTTLS; the upgrade is required, never silently skipped. */
    STARTTLS,
    /** Implicit TLS from the first byte (smtps, usually port 465). */
    TLS
}
