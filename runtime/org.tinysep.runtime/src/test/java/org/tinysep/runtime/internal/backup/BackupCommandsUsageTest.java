package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.runtime.internal.shell.GogoShell;

/** {@code tinysep:backup} and {@code restore} with too many arguments: the usage line, not "Cannot coerce". */
class BackupCommandsUsageTest {

    @TempDir
    Path root;
    private BackupStoreService store;

    @AfterEach
    void stop() throws Exception {
        if (store != null) {
            store.deactivate();
        }
    }

    private GogoShell gogo() {
        store = new BackupStoreService(root, 0, new EventLog() {
            @Override
            public void record(EventKind kind, String origin, String message) {
            }

            @Override
            public List<EventEntry> recent(int max) {
                return List.of();
            }
        });
        return new GogoShell().add("tinysep", new BackupCommands(null, store), "backup", "restore");
    }

    @Test
    void tooManyArgumentsAnswerWithTheUsage() {
        GogoShell gogo = gogo();
        assertEquals("wrong number of arguments (3); usage: tinysep:backup [--with-secrets] [file] (help tinysep:backup"
                + " explains them)", gogo.run("tinysep:backup a b c"));
        assertEquals("wrong number of arguments (3); usage: tinysep:restore [--force] <file> | tinysep:restore --undo"
                + " (help tinysep:restore explains them)", gogo.run("tinysep:restore a b c"));
        assertEquals("missing arguments; usage: tinysep:restore [--force] <file> | tinysep:restore --undo (help"
                + " tinysep:restore explains them)", gogo.run("tinysep:restore"));
    }
}
