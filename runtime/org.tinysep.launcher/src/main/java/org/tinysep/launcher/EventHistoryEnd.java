package org.tinysep.launcher;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.SeekableByteChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * The sequence number of the newest event-log entry kept on disk before this start, read from the files before the
 * framework starts ({@link StartSignals}: every entry after it is this start's). Reading it from the event log
 * service when it registers was a race: on a loaded machine the registration was seen only after this start's
 * entries, so a deaf radio's {@code Monitoring reduced} signal was taken for history and no WARNING came under the
 * banner (DeafRadioIT). The files are the runtime's {@code events-<20 digits>.log} in {@code logDirectory} of
 * {@code etc/org.tinysep.runtime.cfg}, else {@code <var>/log}; a line is {@code <time>\t<sequence>\t<kind>\t…}.
 */
final class EventHistoryEnd {

    static final String RUNTIME_CFG = "org.tinysep.runtime.cfg";
    private static final String FILE_PATTERN = "events-\\d{20}\\.log";
    /** How much of a file's end is read: many lines (an entry is a few hundred bytes at most). */
    static final int TAIL = 64 * 1024;

    private EventHistoryEnd() {
    }

    /**
     * @return the newest sequence number on disk, 0 when there is no history yet, -1 when it cannot be told (a
     *         folder given with a variable, an unreadable file or line): the caller then asks the service instead
     */
    static long read(Path etc, Path var) {
        try {
            Path folder = folder(etc, var);
            if (folder == null) {
                return -1;
            }
            if (!Files.isDirectory(folder)) {
                return 0;
            }
            List<Path> files;
            try (Stream<Path> s = Files.list(folder)) {
                files = s.filter(p -> p.getFileName().toString().matches(FILE_PATTERN)).sorted().toList();
            }
            for (int i = files.size() - 1; i >= 0; i--) { // the newest file may be empty (just rotated)
                String[] lines = tail(files.get(i)).split("\n");
                for (int j = lines.length - 1; j >= 0; j--) {
                    String[] fields = lines[j].split("\t", 3);
                    if (fields.length >= 2) {
                        return Long.parseLong(fields[1]);
                    }
                }
            }
            return 0;
        } catch (IOException | RuntimeException e) {
            return -1;
        }
    }

    /** @return the file's last {@link #TAIL} bytes, whole lines only (a file may hold megabytes: not read whole) */
    private static String tail(Path file) throws IOException {
        try (SeekableByteChannel ch = Files.newByteChannel(file)) {
            long from = Math.max(0, ch.size() - TAIL);
            ByteBuffer buf = ByteBuffer.allocate((int) (ch.size() - from));
            ch.position(from);
            while (buf.hasRemaining() && ch.read(buf) >= 0) {
                // until the end
            }
            String text = new String(buf.array(), 0, buf.position(), StandardCharsets.UTF_8);
            return from == 0 ? text : text.substring(text.indexOf('\n') + 1); // the first line may be cut
        }
    }

    /** @return the log folder, or null when the configured one cannot be resolved here */
    private static Path folder(Path etc, Path var) throws IOException {
        String dir = CfgFile.load(etc.resolve(RUNTIME_CFG)).getProperty("logDirectory", "").strip();
        if (dir.contains("${")) {
            return null;
        }
        return dir.isEmpty() ? var.resolve("log") : Path.of(dir);
    }
}
