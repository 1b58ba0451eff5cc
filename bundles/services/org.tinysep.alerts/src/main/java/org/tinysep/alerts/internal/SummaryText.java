package org.tinysep.alerts.internal;

import java.io.IOException;
import java.nio.file.FileStore;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Instant;
import java.time.LocalDate;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.device.Device;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.log.EventEntry;

/** The words of the daily summary: open alerts, devices offline or failing, disk use of the state folder. */
final class SummaryText {

    private final AlertText words;
    private final Path stateFolder;

    SummaryText(AlertText words, Path stateFolder) {
        this.words = words;
        this.stateFolder = stateFolder;
    }

    String subject(LocalDate day, int openAlerts, int offline) {
        return "TinySEP is running (" + day + "): " + (openAlerts == 0 ? "no open alert" : openAlerts
                + " OPEN ALERT(S)") + ", " + (offline == 0 ? "all devices online" : offline + " device(s) offline");
    }

    /**
     * @param lowBatteries the nodes Sensor Health reports with a low battery, or null without Sensor Health
     * @param reduced      the event log's "monitoring reduced" / "node type mismatch" entries since the last
     *                     summary, or null when the event log cannot be read
     */
    String body(Instant now, Instant due, boolean late, List<Alert> open, List<Device> offline,
            List<SensorHealth> lowBatteries, List<EventEntry> reduced) {
        StringBuilder b = new StringBuilder("TinySEP is running. This summary comes every day at "
                + words.time(due) + "; if one does not come, TinySEP may have stopped: please check on it.\n");
        if (late) {
            b.append("This one is late (sent at ").append(words.fullTime(now))
                    .append("): TinySEP was not running at ").append(words.time(due)).append(".\n");
        }
        b.append("\nOpen alerts: ").append(open.isEmpty() ? "none" : open.size()).append('\n');
        open.forEach(a -> b.append("  alert ").append(a.id()).append(", raised ").append(words.fullTime(a.raisedAt()))
                .append(": ").append(a.subject()).append(" (acknowledge: tinysep:ack ").append(a.id()).append(")\n"));
        reduced(b, reduced);
        b.append("\nDevices offline or failing: ").append(offline.isEmpty() ? "none" : offline.size()).append('\n');
        offline.forEach(d -> b.append("  ").append(d.name()).append(": ").append(d.status()).append('\n'));
        if (lowBatteries == null) {
            b.append("\nLow batteries: not known (Sensor Health, which reads the nodes' battery levels, is not "
                    + "running)\n");
        } else {
            b.append("\nLow batteries: ").append(lowBatteries.isEmpty() ? "none" : lowBatteries.size()).append('\n');
            lowBatteries.forEach(h -> b.append("  ").append(h.name())
                    .append(h.roomName() == null ? "" : " in " + h.roomName()).append(": ")
                    .append(h.node().batteryMillivolts()).append(" mV, replace or recharge it soon\n"));
        }
        b.append("\nState folder ").append(stateFolder).append(": ").append(disk()).append('\n');
        return b.toString();
    }

    private void reduced(StringBuilder b, List<EventEntry> reduced) {
        if (reduced == null) {
            b.append("\nMonitoring reduced since the last summary: not known (the event log cannot be read)\n");
            return;
        }
        b.append("\nMonitoring reduced since the last summary: ").append(reduced.isEmpty() ? "nothing" : reduced.size())
                .append('\n');
        reduced.forEach(e -> b.append("  ").append(words.fullTime(e.time())).append(": ")
                .append(NoticeText.rest(e.message())).append('\n'));
    }

    /** @return e.g. "12.3 MB used by TinySEP; 41.0 GB of 58.0 GB free on its disk (71 %)" */
    String disk() {
        try {
            AtomicLong used = new AtomicLong();
            if (Files.isDirectory(stateFolder)) {
                Files.walkFileTree(stateFolder, new SimpleFileVisitor<>() {
                    @Override
                    public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                        used.addAndGet(attrs.size());
                        return FileVisitResult.CONTINUE;
                    }

                    @Override
                    public FileVisitResult visitFileFailed(Path file, IOException e) {
                        return FileVisitResult.CONTINUE; // a file renamed away meanwhile
                    }
                });
            }
            FileStore store = Files.getFileStore(Files.isDirectory(stateFolder) ? stateFolder
                    : stateFolder.toAbsolutePath().getRoot());
            long total = store.getTotalSpace();
            long free = store.getUsableSpace();
            return mb(used.get()) + " used by TinySEP; " + mb(free) + " of " + mb(total) + " free on its disk ("
                    + (total == 0 ? 0 : free * 100 / total) + " %)";
        } catch (IOException | RuntimeException e) {
            return "disk use unknown (" + e.getMessage() + ")";
        }
    }

    private static String mb(long bytes) {
        return bytes >= 1L << 30 ? String.format("%.1f GB", bytes / (double) (1L << 30))
                : String.format("%.1f MB", bytes / (double) (1L << 20));
    }
}
