package org.tinysep.inactivity.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of Inactivity Recognition (pid {@value InactivityDriver#PID}). */
@ObjectClassDefinition(name = "Inactivity Recognition",
        description = "Calls for help when nobody is active in a room for longer than its limit.")
public @interface InactivityConfig {

    @AttributeDefinition(description = "Minutes allowed after an activity in a room whose type has no limit, or "
            + "by a device that is not placed in a room", min = "1")
    int defaultLimitMinutes() default 120;

    @AttributeDefinition(description = "Limits per room type in minutes, e.g. 'Bathroom=45, Kitchen=90'")
    String typeLimits() default "Bathroom=45, Kitchen=90, Living room=180, Bedroom=600, Hall=30";

    @AttributeDefinition(description = "Overrides per room UID, room name or room type in minutes, "
            + "e.g. 'Bathroom=30, 6f1c...=20'")
    String roomLimits() default "";

    @AttributeDefinition(description = "LEARNED: limits learned per room, time of day and sleep from the home's "
            + "own history (the fixed limits until enough history); THESIS: the thesis's fixed per-room limits")
    Detector detector() default Detector.LEARNED;

    @AttributeDefinition(description = "LEARNED: days with quiet periods a room and time window needs before its "
            + "limit is learned", min = "1")
    int learnMinDays() default 7;

    @AttributeDefinition(description = "LEARNED: days of history learned from", min = "1")
    int learnHistoryDays() default 28;

    @AttributeDefinition(description = "LEARNED: a learned limit is never shorter (minutes)", min = "1")
    int learnFloorMinutes() default 20;

    @AttributeDefinition(description = "LEARNED: never worse than the fixed limits: a learned limit may be shorter "
            + "than the room's fixed limit only when at least this many observed quiet periods support it", min = "0")
    int learnMinPeriodsToShorten() default 30;

    @AttributeDefinition(description = "LEARNED: how many people live in the home; 0: recognised from the history "
            + "(several once, on at least 3 days and a quarter of the days, there was activity in another room while "
            + "a bed mat had been ON for 10 min). With more than 1 (they share the sensors): an activity in a room "
            + "where a bed or seat mat is ON is judged as a resting person's, and a learned limit is never longer "
            + "than the room's fixed limit", min = "0")
    int residents() default 0;

    @AttributeDefinition(description = "LEARNED: the night (sleep in a bedroom) begins at this hour", min = "0",
            max = "23")
    int nightStartHour() default 21;

    @AttributeDefinition(description = "LEARNED: the night ends at this hour", min = "0", max = "23")
    int nightEndHour() default 7;

    @AttributeDefinition(description = "Person nodes: a movement summary whose magnitude spread is above this many "
            + "milli-g is the wearer's movement (the node itself calls at most 30 mg still)", min = "0")
    int personMovingAboveMg() default 30;

    @AttributeDefinition(description = "Person nodes: a node that moved at most this many seconds before a room "
            + "sensor's activity is moving at that moment, so the activity is its wearer's and not another "
            + "person's (about two summary periods of 2 s)", min = "1")
    int personMovingWithinSeconds() default 5;

    @AttributeDefinition(description = "Person nodes: a node that has not moved for this many minutes while room "
            + "sensors see activity nobody else's node explains seems not to be worn: a notice, and its wearer is "
            + "watched by the room sensors until it moves again", min = "1")
    int personNotWornMinutes() default 120;

    @AttributeDefinition(description = "Time zone for the times in alert mails, e.g. 'Europe/Berlin'; empty for "
            + "the system's (also the zone of the learned hours of the day)")
    String timeZone() default "";
}
