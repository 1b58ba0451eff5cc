package org.tinysep.runtime.internal.backup;

/** A backup file that is not a complete, valid backup; the message says why in one line. */
final class BadBackupException extends Exception {

    private static final long serialVersionUID = 1L;

    BadBackupException(String message) {
        super(message);
    }
}
