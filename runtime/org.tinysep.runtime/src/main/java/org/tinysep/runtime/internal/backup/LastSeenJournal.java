package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The last seen times an orderly stop saves in one file, {@code <root>/last-seen.txt} (issue 29, item 4): when the
 * framework stops, each device saves its backup once more, and for most (every node heard from since its last save)
 * only the last seen time moved; writing a backup file per device made a stop of 10,000 nodes write 10,000 files
 * (2,500 nodes: 1.5-10.9 s of a 3-12 s stop on this machine's disk). The journal holds, per device, a last seen time
 * newer than its backup file's; on load it is applied to the backups it is newer than. A device whose backup file is
 * written again (a real change) is dropped from it, so the next stop writes only what is newer than the files.
 * <p>
 * One line per device, {@code <uid> <ISO-8601 instant>}; a line that cannot be read is skipped and reported. A backup
 * archive holds the backup files only: before one is made (or a restore takes its undo copy) the devices kept here
 * have their files written ({@link BackupStoreService#settleJournal()}); a restore replaces the folder and discards
 * the journal.
 */
final class LastSeenJournal {

    static final String FILE = "last-seen.txt";

    private final Path file;
    /** Per device UID, a last seen time newer than the one in its backup file. */
    private final Map<String, Instant> newer = new ConcurrentHashMap<>();

    LastSeenJournal(Path root) {
        this.file = root.resolve(FILE);
    }

    /** @return whether a UID can be written on a line of the journal (no white space) */
    static boolean fits(String uid) {
        return !uid.isEmpty() && uid.codePoints().noneMatch(Character::isWhitespace);
    }

    /** @return whether {@code b} differs from {@code before} in its last seen (and save) time only, later */
    static boolean onlyLastSeenMoved(ComponentBackup before, ComponentBackup b) {
        return b.lastSeen() != null && (before.lastSeen() == null || b.lastSeen().isAfter(before.lastSeen()))
                && withLastSeen(before, b.lastSeen(), b.savedAt()).equals(b);
    }

    static ComponentBackup withLastSeen(ComponentBackup b, Instant lastSeen, Instant savedAt) {
        return new ComponentBackup(b.uid(), b.kind(), b.driverUid(), b.driverName(), b.type(), b.name(),
                b.parameters(), b.nodeAddress(), b.nodeTypes(), lastSeen, b.state(), savedAt);
    }

    /** Keeps {@code lastSeen} for the device, to be written by {@link #write()}. */
    void note(String uid, Instant lastSeen) {
        newer.merge(uid, lastSeen, (a, b) -> a.isAfter(b) ? a : b);
    }

    /** The device's backup file is written again: it holds the newest last seen time. */
    void forget(String uid) {
        newer.remove(uid);
    }

    int size() {
        return newer.size();
    }

    /** @return the UIDs of the devices whose newest last seen time is kept here */
    Set<String> uids() {
        return Set.copyOf(newer.keySet());
    }

    /**
     * Reads the journal file, if any, into this journal.
     *
     * @param problem told of each line that cannot be read
     * @return the last seen times read, by UID
     */
    Map<String, Instant> read(Consumer<String> problem) throws IOException {
        Map<String, Instant> out = new LinkedHashMap<>();
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException none) {
            return out;
        }
        int n = 0;
        for (String line : text.split("\n")) {
            n++;
            if (line.isBlank()) {
                continue;
            }
            int space = line.indexOf(' ');
            try {
                if (space <= 0) {
                    throw new DateTimeParseException("no time", line, 0);
                }
                out.put(line.substring(0, space), Instant.parse(line.substring(space + 1).strip()));
            } catch (DateTimeParseException e) {
                problem.accept(FILE + " line " + n + " is not '<uid> <time>': skipped");
            }
        }
        out.forEach(this::note);
        return out;
    }

    /** Writes every kept last seen time, atomically, in one file (none: the file is deleted). */
    void write() throws IOException {
        Map<String, Instant> sorted = new TreeMap<>(newer);
        if (sorted.isEmpty()) {
            AtomicFiles.delete(file);
            return;
        }
        StringBuilder out = new StringBuilder(sorted.size() * 64);
        sorted.forEach((uid, at) -> out.append(uid).append(' ').append(at).append('\n'));
        AtomicFiles.write(file, out.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** Forgets every kept time and deletes the file (the folder was replaced by a restore). */
    void discard() throws IOException {
        newer.clear();
        AtomicFiles.delete(file);
    }
}
