package org.tinysep.api.alert;

/** Why a message about an alert was sent. */
public enum NotificationStep {
    /** The first message, to the first contact. */
    FIRST,
    /** The same alert again, to the contacts reached so far, because nobody acknowledged it. */
    REPEAT,
    /** The alert handed on to the next contact of the list, because nobody acknowledged it. */
    ESCALATION,
    /** The cause ended by itself: everyone told of the alert is told it is over. */
    ALL_CLEAR
}
