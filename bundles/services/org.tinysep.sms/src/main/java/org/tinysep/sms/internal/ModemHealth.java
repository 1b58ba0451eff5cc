package org.tinysep.sms.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.device.DeviceStatus;

/**
 * Whether SMS can go out, in plain words: gammu-smsd's spool folders exist, a live gammu-smsd process is behind its
 * pid file, and no SMS has waited in the outbox for longer than {@code stuckSeconds} (gammu-smsd keeps running when
 * the modem is unplugged or has no network, but sends nothing).
 */
final class ModemHealth {

    private final Spool spool;
    private final Path pidFile;
    private final Duration stuck;
    private final Clock clock;
    private DeviceStatus last;

    ModemHealth(Spool spool, String pidFile, int stuckSeconds, Clock clock) {
        this.spool = spool;
        this.pidFile = pidFile == null || pidFile.isBlank() ? null : Path.of(pidFile.strip());
        this.stuck = Duration.ofSeconds(stuckSeconds);
        this.clock = clock;
    }

    synchronized DeviceStatus status() {
        DeviceStatus.State state = DeviceStatus.State.ERROR;
        String detail;
        List<String> missing = spool.missing();
        Optional<String> notRunning = notRunning();
        int waiting;
        if (!missing.isEmpty()) {
            detail = "gammu-smsd's spool folder(s) " + String.join(", ", missing) + " do not exist: SMS cannot go "
                    + "out until gammu-smsd is set up (docs/alerts-by-phone.md); alerts go by the other channels";
        } else if (notRunning.isPresent()) {
            detail = notRunning.get() + ": SMS cannot go out; alerts go by the other channels";
        } else if ((waiting = spool.waitingLongerThan(stuck, clock.instant())) > 0) {
            detail = waiting + " SMS waiting in the outbox for more than " + stuck.toSeconds() + " s: the GSM modem "
                    + "is unplugged, has no network or no credit (gammu-smsd runs but does not send); alerts go by "
                    + "the other channels";
        } else {
            state = DeviceStatus.State.ONLINE;
            detail = "gammu-smsd is running" + (pidFile == null ? " (not checked: no pid file configured)" : "")
                    + " and sends from " + spool.folder("outbox");
        }
        if (last == null || last.state() != state || !last.detail().equals(detail)) {
            last = new DeviceStatus(state, detail, clock.instant());
        }
        return last;
    }

    /** @return why gammu-smsd is not running, or empty when it is (or is not checked) */
    private Optional<String> notRunning() {
        if (pidFile == null) {
            return Optional.empty();
        }
        if (!Files.exists(pidFile)) {
            return Optional.of("gammu-smsd is not running (its pid file " + pidFile + " does not exist)");
        }
        try {
            long pid = Long.parseLong(Files.readString(pidFile).strip());
            boolean alive = ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false);
            return alive ? Optional.empty() : Optional.of("gammu-smsd is not running (no process " + pid
                    + " as its pid file " + pidFile + " says)");
        } catch (IOException | NumberFormatException e) {
            return Optional.of("gammu-smsd's pid file " + pidFile + " cannot be read (" + e.getMessage() + ")");
        }
    }
}
