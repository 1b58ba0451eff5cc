package org.tinysep.inactivity.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.device.support.files.AtomicFiles;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.QuietGaps;
import org.tinysep.inactivity.internal.learn.Sighting;

/**
 * The learned detector's own memory: what it has learned from, in a file of its own beside the
 * rotating event log, written atomically, so a flood of event-log entries (a flapping node) cannot make it forget.
 * UTF-8 lines of tab-separated fields (text escaped: {@code \\ \t \n \r}):
 * <pre>
 * tinysep-learned-history 1
 * covered  &lt;instant&gt;                                 the later of the platform time it was saved and the newest time
 *                                                   it holds: the log is read only after it
 * S  &lt;at&gt; &lt;room uid&gt; &lt;room name&gt; &lt;room type&gt; &lt;in bed 0|1&gt; &lt;seated 0|1&gt;   a sighting
 * A  &lt;from&gt; &lt;to&gt;                                  a time the flat was empty
 * W  &lt;since&gt;                                        the flat is empty since
 * R  &lt;at&gt; &lt;device uid&gt; &lt;in bed&gt; &lt;seated&gt; &lt;up&gt; [&lt;OFF kind&gt; &lt;device before&gt;]   a logged activity
 *                                                   of a device not yet a source (the last two for a flush or
 *                                                   appliance turning OFF: {@link HistoryFromLog.Raw#after})
 * </pre>
 * A line that cannot be read is skipped and counted. Bounded by the learner's history window ({@code
 * learnHistoryDays}; sightings in one room less than a minute apart are one).
 */
final class LearnedMemory {

    static final String HEADER = "tinysep-learned-history 1";

    /** What the file held. */
    record Content(HistoryLearner.Memory memory, List<HistoryFromLog.Raw> pending, Instant covered, int damaged) {
    }

    private final Path file;

    LearnedMemory(Path file) {
        this.file = file;
    }

    Path file() {
        return file;
    }

    /** Writes it atomically (temp file, fsync, rename). */
    void save(HistoryLearner.Memory m, List<HistoryFromLog.Raw> pending, Instant covered) throws IOException {
        StringBuilder b = new StringBuilder(HEADER).append('\n');
        b.append("covered\t").append(covered).append('\n');
        for (Sighting s : m.sightings()) {
            b.append("S\t").append(s.at()).append('\t').append(esc(s.room())).append('\t').append(esc(s.roomName()))
                    .append('\t').append(esc(s.roomType())).append('\t').append(bit(s.inBed())).append('\t')
                    .append(bit(s.seated())).append('\t').append(bit(s.upFromBed())).append('\n');
        }
        for (QuietGaps.Away a : m.away()) {
            b.append("A\t").append(a.from()).append('\t').append(a.to()).append('\n');
        }
        if (m.awaySince() != null) {
            b.append("W\t").append(m.awaySince()).append('\n');
        }
        for (HistoryFromLog.Raw r : pending) {
            b.append("R\t").append(r.at()).append('\t').append(esc(r.device())).append('\t').append(bit(r.inBed()))
                    .append('\t').append(bit(r.seated())).append('\t').append(bit(r.upFromBed()));
            if (r.after() != null) {
                b.append('\t').append(r.off().name()).append('\t').append(esc(r.after()));
            }
            b.append('\n');
        }
        AtomicFiles.write(file, b.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** @return what the file held, or null when there is none (or it is not such a file) */
    Content load() throws IOException {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            return null;
        }
        if (lines.isEmpty() || !HEADER.equals(lines.get(0))) {
            return null;
        }
        List<Sighting> sightings = new ArrayList<>();
        List<QuietGaps.Away> away = new ArrayList<>();
        List<HistoryFromLog.Raw> pending = new ArrayList<>();
        Instant covered = null;
        Instant since = null;
        int damaged = 0;
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split("\t", -1);
            try {
                switch (f[0] + "/" + f.length) {
                    case "covered/2" -> covered = Instant.parse(f[1]);
                    case "S/7" -> sightings.add(new Sighting(Instant.parse(f[1]), unesc(f[2]), unesc(f[3]),
                            unesc(f[4]), "1".equals(f[5]), "1".equals(f[6])));
                    case "S/8" -> sightings.add(new Sighting(Instant.parse(f[1]), unesc(f[2]), unesc(f[3]),
                            unesc(f[4]), "1".equals(f[5]), "1".equals(f[6]), "1".equals(f[7])));
                    case "R/6" -> pending.add(new HistoryFromLog.Raw(Instant.parse(f[1]), unesc(f[2]),
                            "1".equals(f[3]), "1".equals(f[4]), "1".equals(f[5])));
                    case "R/8" -> pending.add(new HistoryFromLog.Raw(Instant.parse(f[1]), unesc(f[2]),
                            "1".equals(f[3]), "1".equals(f[4]), "1".equals(f[5]), PresenceKind.valueOf(f[6]),
                            unesc(f[7])));
                    case "A/3" -> away.add(new QuietGaps.Away(Instant.parse(f[1]), Instant.parse(f[2])));
                    case "W/2" -> since = Instant.parse(f[1]);
                    case "R/5" -> pending.add(new HistoryFromLog.Raw(Instant.parse(f[1]), unesc(f[2]),
                            "1".equals(f[3]), "1".equals(f[4])));
                    default -> damaged++;
                }
            } catch (RuntimeException e) {
                damaged++;
            }
        }
        return new Content(new HistoryLearner.Memory(sightings, away, since), pending, covered, damaged);
    }

    private static String bit(boolean b) {
        return b ? "1" : "0";
    }

    static String esc(String s) {
        return s.replace("\\", "\\\\").replace("\t", "\\t").replace("\n", "\\n").replace("\r", "\\r");
    }

    static String unesc(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c != '\\' || i + 1 == s.length()) {
                b.append(c);
                continue;
            }
            char n = s.charAt(++i);
            b.append(switch (n) {
                case 't' -> '\t';
                case 'n' -> '\n';
                case 'r' -> '\r';
                default -> n;
            });
        }
        return b.toString();
    }
}
