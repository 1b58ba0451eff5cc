package org.tinysep.mqtt.internal;

/**
 * What the bridge shows as its device's parameters, replaced as a whole on the bridge's thread.
 *
 * @param link             connected / connecting / offline, in words
 * @param waitingAlerts    alert messages on disk not yet acknowledged by the broker
 * @param waitingState     state topics with a newer value not yet sent
 * @param delivered        messages the broker acknowledged since the start
 * @param acceptedCommands commands carried out
 * @param rejectedCommands commands refused (each answered on command/result)
 * @param refusedUnauthorised commands refused because not signed (or badly, stale, replayed) or switched off
 * @param droppedResults   command results dropped because more than 1000 waited
 * @param devices          devices published
 */
record Figures(String link, int waitingAlerts, int waitingState, long delivered, long acceptedCommands,
        long rejectedCommands, long refusedUnauthorised, long droppedResults, int devices) {

    static final Figures IDLE = new Figures("idle: no brokerUrl configured", 0, 0, 0, 0, 0, 0, 0, 0);
}
