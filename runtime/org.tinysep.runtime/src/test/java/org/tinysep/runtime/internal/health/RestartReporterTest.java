package org.tinysep.runtime.internal.health;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.runtime.internal.log.EventLogService;

/**
 * The launcher's restart note reaches the event log once, in its own words, and stays until it can be mailed (the
 * mail itself: the launcher's SupervisorIT, with the real Mail Manager and an SMTP server).
 */
class RestartReporterTest {

    @TempDir
    Path var;

    @Test
    void theRestartIsLoggedOnceAndTheNoteWaitsForTheMailManager() throws Exception {
        Path note = var.resolve(RestartReporter.FILE);
        Files.writeString(note, "cause=stopped responding\nat=2026-03-02T08\\:58\\:00Z\nmessage=TinySEP was "
                + "restarted at 10\\:02 after it stopped responding at 09\\:58 (Europe/Berlin)\n");
        EventLogService events = new EventLogService();
        RestartReporter first = reporter(events);
        first.activate(note);
        RestartReporter second = reporter(events); // restarted again before any Mail Manager came
        second.activate(note);

        List<EventEntry> problems = events.recent(10).stream().filter(e -> e.kind() == EventKind.PROBLEM).toList();
        assertEquals(1, problems.size(), problems.toString());
        assertEquals("TinySEP was restarted at 10:02 after it stopped responding at 09:58 (Europe/Berlin)",
                problems.get(0).message());
        assertEquals(RestartReporter.ORIGIN, problems.get(0).origin());
        assertTrue(Files.readString(note).contains("logged=true"), "kept for the mail, marked as logged");
    }

    @Test
    void noNoteNoEntry() {
        EventLogService events = new EventLogService();
        reporter(events).activate(var.resolve(RestartReporter.FILE));
        reporter(events).activate((Path) null);
        assertTrue(events.recent(10).isEmpty());
    }

    private static RestartReporter reporter(EventLogService events) {
        RestartReporter r = new RestartReporter();
        r.eventLog = events;
        return r;
    }
}
