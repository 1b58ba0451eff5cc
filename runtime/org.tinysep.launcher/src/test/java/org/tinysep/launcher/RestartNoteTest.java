package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneId;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The restart sentence and when a start counts as a restart after a failure (files in a real folder). */
class RestartNoteTest {

    private static final ZoneId BERLIN = ZoneId.of("Europe/Berlin");

    @TempDir
    Path var;

    @Test
    void theSentenceSaysWhenAndWhyInPlainWords() {
        RestartNote hung = new RestartNote(RestartNote.HUNG, Instant.parse("2026-03-02T08:58:10Z"));
        assertEquals("TinySEP was restarted at 10:02 after it stopped responding at 09:58 (Europe/Berlin)",
                hung.sentence(Instant.parse("2026-03-02T09:02:40Z"), BERLIN));
        assertEquals("TinySEP was restarted at 07:15 after it stopped responding at 23:40 on 1 Mar (Europe/Berlin)",
                new RestartNote(RestartNote.HUNG, Instant.parse("2026-03-01T22:40:00Z"))
                        .sentence(Instant.parse("2026-03-02T06:15:00Z"), BERLIN));
        assertTrue(RestartNote.exited(1).cause().contains("exit code 1"));
    }

    @Test
    void aCleanStopIsNoRestartButARunningHeartbeatIs() throws Exception {
        HeartbeatFile beat = new HeartbeatFile(var);
        beat.write("STOPPED", Instant.parse("2026-03-02T08:00:00Z"));
        assertEquals(Optional.empty(), HeartbeatFile.noteRestart(var, Instant.now(), BERLIN));

        beat.write("RUNNING", Instant.parse("2026-03-02T08:58:00Z")); // then a crash, a power cut, a kill
        String sentence = HeartbeatFile.noteRestart(var, Instant.parse("2026-03-02T09:02:00Z"), BERLIN).orElseThrow();
        assertEquals("TinySEP was restarted at 10:02 after it stopped without shutting down cleanly (a crash, a "
                + "hang, a power cut or a kill); its last sign of life was at 09:58 (Europe/Berlin)", sentence);
        assertEquals(sentence, StateFile.read(var.resolve(RestartNote.FILE)).orElseThrow().get("message"));
    }

    @Test
    void theSupervisorsNoteWinsAndACompletedNoteIsKeptUntilReported() throws Exception {
        new HeartbeatFile(var).write("RUNNING", Instant.parse("2026-03-02T08:58:00Z"));
        new RestartNote(RestartNote.HUNG, Instant.parse("2026-03-02T08:58:00Z")).write(var);
        assertEquals("TinySEP was restarted at 10:02 after it stopped responding at 09:58 (Europe/Berlin)",
                HeartbeatFile.noteRestart(var, Instant.parse("2026-03-02T09:02:00Z"), BERLIN).orElseThrow());

        new HeartbeatFile(var).write("STOPPED", Instant.parse("2026-03-02T09:30:00Z")); // not mailed, clean stop
        assertEquals(Optional.empty(), HeartbeatFile.noteRestart(var, Instant.parse("2026-03-02T10:00:00Z"), BERLIN));
        assertTrue(StateFile.read(var.resolve(RestartNote.FILE)).orElseThrow().get("message")
                .startsWith("TinySEP was restarted at 10:02 after it stopped responding at 09:58"));
    }
}
