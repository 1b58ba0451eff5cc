package org.tinysep.inactivity.internal.learn;

import java.util.HashMap;
import java.util.Map;

/**
 * The home's residents as the installer declares them ({@link LearningSettings#residents()}), and what follows for
 * a home of several (issue 28, item 1 on a two-resident home). The residents share the sensors: nothing tells whose
 * an event is, and one resident's activity ends the quiet period of all. So with several residents:
 * <ul>
 * <li><b>Someone resting in the room.</b> An activity (a movement, a door) in a room where a bed or seat mat is ON
 * begins the quiet period of a resting person, as if the mat had just turned ON: someone lies or sits there, and
 * the one who moved is with them (or is them, moving on the mat). Its limit is the in-bed or sitting one, not the
 * room's limit for walking through — a walk-through limit learned from two people's chopped periods called for help
 * while one sat watching television with the other.</li>
 * <li><b>Never longer than the fixed limit</b> ({@link LearnedLimits#decide}): a collapse is found only once the
 * others are quiet too, so every minute a learned limit adds to the fixed one is a collapse missed while the others
 * move about, and a long limit learned from the home's history may be the other resident's long sits.</li>
 * </ul>
 * With one resident nothing changes: a movement of the only person is that person getting up. Not declared
 * ({@code residents} 0, the default), the home is taken for several residents once its history shows two people at
 * once on enough days ({@link TwoAtOnce}, asked at every learning, {@link #found}).
 * The mats are kept by device (two seat mats in one living room: one turning OFF leaves the other ON). Thread-safe.
 */
public final class Residents {

    private record Mat(String room, boolean bed) {
    }

    private final int count;
    private final Map<String, Mat> on = new HashMap<>();
    private volatile TwoAtOnce.Finding found = TwoAtOnce.Finding.NONE;

    /** @param count the home's residents as declared, at least 1, or 0: from the history ({@link TwoAtOnce}) */
    public Residents(int count) {
        if (count < 0) {
            throw new IllegalArgumentException("a home has at least 1 resident (0: from the history), was " + count);
        }
        this.count = count;
    }

    /** @return whether the home has several residents (the rules above apply): declared, or seen in the history */
    public boolean several() {
        return count > 1 || count == 0 && found.several();
    }

    /** @return whether the residents are recognised from the history (none declared) */
    public boolean fromHistory() {
        return count == 0;
    }

    /** What the history showed at the latest learning (a home with its residents declared ignores it). */
    public void found(TwoAtOnce.Finding f) {
        found = f;
    }

    /** @return why the rules of several residents apply, for an explanation, e.g. "the home has 2 residents" */
    public String words() {
        return count > 1 ? "the home has " + count + " residents" : found.words();
    }

    /**
     * A bed mat ({@code bed}) or seat mat is ON or OFF now (also its first report after a start: its state).
     *
     * @param device the mat's device (any stable key)
     * @param room   its room (the key {@link Sighting#room()} uses)
     */
    public synchronized void mat(String device, String room, boolean bed, boolean isOn) {
        if (count == 1) {
            return; // one resident declared: nothing to keep
        }
        if (isOn) {
            on.put(device, new Mat(room == null ? "" : room, bed));
        } else {
            on.remove(device);
        }
    }

    /** @return {@code s} read with the mats now ON in its room ({@link #read(Sighting, boolean, boolean)}) */
    public Sighting read(Sighting s) {
        return several() ? resting(s) : s;
    }

    /**
     * @return {@code s} read as with several residents, whether the home has them or not yet (the core replay marks
     *         its activities once and asks {@link #several()} when it plays them); as {@code s} with one declared
     */
    public Sighting resting(Sighting s) {
        boolean bed = false;
        boolean seat = false;
        synchronized (this) {
            for (Mat m : on.values()) {
                if (m.room().equals(s.room())) {
                    bed |= m.bed();
                    seat |= !m.bed();
                }
            }
        }
        return read(s, bed, seat);
    }

    /**
     * @param original the sighting as the device reported it
     * @param read     the same through {@link #read(Sighting)}
     * @param limit    the limit found for {@code read}
     * @return {@code limit}, its explanation preceded by why the activity was read as a resting person's when it was
     */
    public Limit explain(Sighting original, Sighting read, Limit limit) {
        if (read == original) {
            return limit;
        }
        String mat = read.inBed() ? "a bed mat" : "a seat mat";
        String who = read.inBed() ? "someone lies there" : "someone sits there";
        return new Limit(limit.limit(), limit.asleep(), mat + " in " + read.roomName() + " is on and " + words()
                + ": " + who + ", so the quiet after this activity is a "
                + (read.inBed() ? "resting" : "sitting") + " person's; " + limit.explanation());
    }

    /**
     * The rule "someone resting in the room" of a home with several residents (the caller checked {@link #several()}).
     *
     * @param bedOn  a bed mat in the sighting's room is ON
     * @param seatOn a seat mat in it is ON
     * @return {@code s} as the in-bed (a bed mat first) or sitting sighting it is with a mat ON in its room; a mat's
     *         own change (in bed, sat down, getting up) is left as it is
     */
    public static Sighting read(Sighting s, boolean bedOn, boolean seatOn) {
        if (s.inBed() || s.seated() || s.upFromBed() || !bedOn && !seatOn) {
            return s;
        }
        return new Sighting(s.at(), s.room(), s.roomName(), s.roomType(), bedOn, !bedOn, false);
    }
}
