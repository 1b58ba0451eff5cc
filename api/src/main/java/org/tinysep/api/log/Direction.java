package org.tinysep.api.log;

/** Direction of a logged packet, seen from the platform. */
public enum Direction {
    RECEIVED,
    SENT
}
