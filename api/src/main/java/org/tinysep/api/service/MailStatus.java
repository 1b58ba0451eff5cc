package org.tinysep.api.service;

/** State of the mail manager's delivery (thesis A.14, extended). */
public enum MailStatus {
    /** Nothing waiting. */
    IDLE,
    /** Messages queued, sending or retrying. */
    SENDING,
    /** The last attempt failed; messages are kept and retried with back-off. */
    RETRYING,
    /** Not configured (no SMTP host): messages are written to the log only. */
    NOT_CONFIGURED
}
