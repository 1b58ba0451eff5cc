package org.tinysep.mqtt.board.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.time.Clock;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** A flood from one flat delays only that flat; its queue is bounded and keeps its alerts. */
class IntakeTest {

    @Test
    void aFloodingFlatDoesNotStallTheOthers() throws Exception {
        Board board = new Board("tinysep", 100);
        List<String> order = new CopyOnWriteArrayList<>();
        CountDownLatch hold = new CountDownLatch(1);
        CountDownLatch done = new CountDownLatch(1);
        Intake.Applied applied = (topic, payload, changed) -> {
            order.add(topic);
            if (order.size() == 1) {
                await(hold); // the worker is busy with the first message while the flood arrives
            }
            if (topic.equals("tinysep/quiet/status")) {
                done.countDown();
            }
        };
        try (Intake intake = new Intake(board, Clock.systemUTC(), applied)) {
            intake.offer("tinysep/noisy/status", bytes("online"));
            intake.offer("tinysep/noisy/alert/1", bytes(BoardTest.alert(1, "OPEN", 1).replace("\"17\"", "\"noisy\"")));
            for (int i = 0; i < 2 * Intake.PER_FLAT; i++) {
                intake.offer("tinysep/noisy/occupancy", bytes("{\"state\":\"OCCUPIED\"}"));
            }
            intake.offer("tinysep/quiet/status", bytes("online"));
            hold.countDown();
            assertTrue(done.await(30, TimeUnit.SECONDS));
            int quiet = order.indexOf("tinysep/quiet/status");
            assertTrue(quiet <= 3, "the quiet flat waited behind " + quiet + " messages of the noisy one");
            assertTrue(intake.dropped() >= Intake.PER_FLAT - 1, "dropped " + intake.dropped());
        }
        assertTrue(order.contains("tinysep/noisy/alert/1"), "the flood must not push out the alert");
        assertEquals(1, board.find("noisy").orElseThrow().snapshot().alerts().size());
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private static void await(CountDownLatch latch) {
        try {
            latch.await(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
