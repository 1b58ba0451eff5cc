package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The queue on disk: one {@code <id>.mail} file per message (UTF-8 properties), written atomically (temporary
 * file, fsync, rename) and deleted once sent. Damaged files are moved to {@code damaged/}, messages the server
 * refused for good to {@code failed/}, so nothing disappears without a trace.
 */
final class MailSpool {

    private static final String SUFFIX = ".mail";
    private static final String NOTICE = "undelivered.txt";

    private final Path dir;

    MailSpool(Path dir) {
        this.dir = dir;
    }

    Path dir() {
        return dir;
    }

    /** Writes one message durably. */
    void write(MailMessage m) throws IOException {
        AtomicFiles.createPrivateDirectories(dir);
        Properties p = new Properties();
        p.setProperty("id", Long.toString(m.id()));
        p.setProperty("queuedAt", m.queuedAt().toString());
        p.setProperty("subject", m.subject());
        p.setProperty("body", m.body());
        if (!m.pending().isEmpty()) {
            p.setProperty("pending", String.join(",", m.pending()));
        }
        if (!m.failed().isEmpty()) {
            p.setProperty("failed", String.join(",", m.failed()));
        }
        if (!m.to().isEmpty()) {
            p.setProperty("to", String.join(",", m.to()));
        }
        if (m.firstFailure() != null) {
            p.setProperty("firstFailure", m.firstFailure().toString());
        }
        Path tmp = dir.resolve(m.id() + SUFFIX + ".tmp");
        try (Writer w = Files.newBufferedWriter(AtomicFiles.createPrivateFile(tmp), StandardCharsets.UTF_8)) {
            p.store(w, "TinySEP mail spool");
        }
        try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE)) {
            ch.force(true);
        }
        Files.move(tmp, file(m), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
    }

    /** Removes a sent message. */
    void delete(MailMessage m) throws IOException {
        Files.deleteIfExists(file(m));
    }

    /** Moves a queued message to another spool folder (the configuration changed); a failure is reported. */
    void moveTo(MailSpool target, MailMessage m, Consumer<String> problems) {
        try {
            target.write(m);
            delete(m);
        } catch (IOException e) {
            problems.accept("cannot move " + m + " from " + dir + " to " + target.dir + ": " + e);
        }
    }

    /** Keeps a message that could not be delivered to some recipients in {@code failed/} (with whom it failed for). */
    void moveToFailed(MailMessage m) throws IOException {
        new MailSpool(dir.resolve("failed")).write(m);
        delete(m);
    }

    /**
     * Reads every spooled message in sending order. Unreadable files are moved to {@code damaged/} and reported;
     * left-over temporary files (a write cut short) are deleted.
     */
    List<MailMessage> load(Consumer<String> problems) {
        List<MailMessage> all = new ArrayList<>();
        if (!Files.isDirectory(dir)) {
            return all;
        }
        List<Path> files;
        try (Stream<Path> s = Files.list(dir)) {
            files = s.filter(Files::isRegularFile).sorted().toList();
        } catch (IOException e) {
            problems.accept("cannot list mail spool " + dir + ": " + e.getMessage());
            return all;
        }
        for (Path f : files) {
            String name = f.getFileName().toString();
            if (name.endsWith(".tmp")) {
                deleteQuietly(f, problems);
            } else if (name.endsWith(SUFFIX)) {
                try {
                    all.add(read(f));
                } catch (IOException | RuntimeException e) {
                    moveAside(f, e, problems);
                }
            }
        }
        all.sort((a, b) -> Long.compare(a.id(), b.id()));
        return all;
    }

    private static MailMessage read(Path f) throws IOException {
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(f, StandardCharsets.UTF_8)) {
            p.load(r);
        }
        String id = p.getProperty("id");
        String queued = p.getProperty("queuedAt");
        String subject = p.getProperty("subject");
        String body = p.getProperty("body");
        if (id == null || queued == null || subject == null || body == null) {
            throw new IOException("missing id, queuedAt, subject or body");
        }
        String first = p.getProperty("firstFailure");
        return new MailMessage(Long.parseLong(id.strip()), Instant.parse(queued.strip()), subject, body,
                list(p.getProperty("pending")), list(p.getProperty("failed")),
                first == null ? null : Instant.parse(first.strip()), list(p.getProperty("to")));
    }

    private static List<String> list(String v) {
        return v == null || v.isBlank() ? List.of()
                : java.util.Arrays.stream(v.split(",")).map(String::strip).filter(x -> !x.isEmpty()).toList();
    }

    /**
     * Remembers, durably, that an alert could not be delivered, so the device shows it after a restart too.
     *
     * @param notice a sentence for the user, or null to forget it (a delivery succeeded)
     */
    void notice(String notice) throws IOException {
        Path f = dir.resolve(NOTICE);
        if (notice == null) {
            Files.deleteIfExists(f);
            return;
        }
        AtomicFiles.createPrivateDirectories(dir);
        AtomicFiles.write(f, notice.getBytes(StandardCharsets.UTF_8)); // its temporary file is owner-only
    }

    /** @return the remembered undelivered-alert notice, or null */
    String notice() {
        try {
            Path f = dir.resolve(NOTICE);
            return Files.isRegularFile(f) ? Files.readString(f, StandardCharsets.UTF_8).strip() : null;
        } catch (IOException e) {
            return "an earlier alert may not have been delivered (" + NOTICE + " unreadable: " + e.getMessage() + ")";
        }
    }

    private void moveAside(Path f, Exception why, Consumer<String> problems) {
        try {
            Path damaged = Files.createDirectories(dir.resolve("damaged"));
            Files.move(f, damaged.resolve(f.getFileName()), StandardCopyOption.REPLACE_EXISTING);
            problems.accept("damaged spool file " + f.getFileName() + " moved to " + damaged + ": " + why);
        } catch (IOException e) {
            problems.accept("damaged spool file " + f + " (" + why + ") could not be moved aside: " + e);
        }
    }

    private static void deleteQuietly(Path f, Consumer<String> problems) {
        try {
            Files.deleteIfExists(f);
        } catch (IOException e) {
            problems.accept("cannot delete left-over " + f + ": " + e.getMessage());
        }
    }

    private Path file(MailMessage m) {
        return dir.resolve(String.format("%020d", m.id()) + SUFFIX);
    }
}
