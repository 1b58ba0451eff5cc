package org.tinysep.falldetection.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.falldetection.internal.Nodes.LYING;
import static org.tinysep.falldetection.internal.Nodes.UPRIGHT;
import static org.tinysep.falldetection.internal.Nodes.summary;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.person.Acceleration;

/** The wearer's upright, learned from the node's summaries while they walk. */
class UprightTest {

    /** A node clipped on tilted by about 35°, as SisFall's elderly subject SE01 wore it (not the node's y axis). */
    static final Acceleration TILTED = new Acceleration(30, -820, -570);
    private final FallDetector detector = new FallDetector(FallDetectorTest.SETTINGS);

    @Test
    void unknownUntilTheWearerWalks() {
        for (int t = 2; t <= 60; t += 2) {
            detector.summary(summary(t, UPRIGHT, 10, 1010)); // standing or sitting still: no evidence
        }
        assertEquals(Optional.empty(), detector.upright());
    }

    @Test
    void walkingTeachesHowTheNodeHangsOnThisWearer() {
        for (int t = 2; t <= 6; t += 2) {
            detector.summary(summary(t, TILTED, 260, 1700));
        }
        Acceleration u = detector.upright().orElseThrow(() -> new AssertionError("6 s of walking teach the upright"));
        assertTrue(FallDetector.angle(u, TILTED) < 1, "learned " + u);
        assertTrue(FallDetector.angle(u, UPRIGHT) > 30, "not the node's fixed axis: " + u);
    }

    @Test
    void aTurnInBedTeachesNothing() {
        // moving, but through changing postures (back, side, back): no run of three alike
        detector.summary(summary(2, LYING, 300, 1800));
        detector.summary(summary(4, new Acceleration(990, -60, 100), 300, 1800));
        detector.summary(summary(6, LYING, 300, 1800));
        detector.summary(summary(8, new Acceleration(990, -60, 100), 300, 1800));
        assertEquals(Optional.empty(), detector.upright());
    }

    @Test
    void movementThatIsInterruptedIsNotARun() {
        detector.summary(summary(2, UPRIGHT, 260, 1700));
        detector.summary(summary(4, UPRIGHT, 260, 1700));
        detector.summary(summary(10, UPRIGHT, 260, 1700)); // 4 s of no report between: not one walk
        assertEquals(Optional.empty(), detector.upright());
    }

    @Test
    void aNodePutOnDifferentlyIsFollowed() {
        for (int t = 2; t <= 6; t += 2) {
            detector.summary(summary(t, UPRIGHT, 260, 1700));
        }
        for (int t = 8; t <= 8 + 6 * 2 * Upright.KEEP; t += 2) {
            detector.summary(summary(t, TILTED, 260, 1700));
        }
        assertTrue(FallDetector.angle(detector.upright().orElseThrow(), TILTED) < 1,
                "after many walks the old way is forgotten: " + detector.upright());
    }
}
