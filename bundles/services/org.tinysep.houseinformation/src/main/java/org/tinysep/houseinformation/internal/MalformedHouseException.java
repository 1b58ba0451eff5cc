package org.tinysep.houseinformation.internal;

/** A house file that cannot be used: bad XML, unknown neighbour, duplicate UID, blank name or type. */
final class MalformedHouseException extends Exception {

    private static final long serialVersionUID = 1L;

    MalformedHouseException(String message) {
        super(message);
    }

    MalformedHouseException(String message, Throwable cause) {
        super(message, cause);
    }
}
