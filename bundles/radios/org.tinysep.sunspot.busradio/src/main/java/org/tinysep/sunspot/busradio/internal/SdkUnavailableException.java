package org.tinysep.sunspot.busradio.internal;

/** The Sun SPOT SDK is not installed: its classes are missing or it offers no radiogram protocol. */
final class SdkUnavailableException extends Exception {

    private static final long serialVersionUID = 1L;

    /** @param detail what exactly was missing, e.g. the missing class */
    SdkUnavailableException(String detail) {
        super("Sun SPOT SDK not installed (" + detail + ")", null, false, false);
    }
}
