package org.tinysep.drivers.internal;

/** The drivers file cannot be read: the message names the file, where, and why, in one line. */
final class MalformedDriversException extends Exception {

    private static final long serialVersionUID = 1L;

    MalformedDriversException(String message, Throwable cause) {
        super(message, cause);
    }
}
