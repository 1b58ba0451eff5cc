package org.tinysep.sms.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.testing.TestPlatform;

/**
 * The GSM modem as a device (issue 27): its status follows {@link ModemHealth} on a real spool folder — ERROR in
 * words while no gammu-smsd process is behind the pid file, ONLINE once one is — and each change is a STATUS entry.
 */
class ModemDeviceTest {

    @TempDir
    Path dir;

    @Test
    void theModemIsInErrorInWordsWhileGammuSmsdIsNotRunning() throws Exception {
        for (String f : List.of("outbox", "inbox", "sent", "error")) {
            Files.createDirectories(dir.resolve(f));
        }
        Path pid = dir.resolve("gammu-smsd.pid");
        ModemHealth health = new ModemHealth(new Spool(dir), pid.toString(), 60, Clock.systemUTC());
        TestPlatform platform = new TestPlatform();
        ModemDevice modem = new ModemDevice(platform.context(ModemDriver.NAME), List.of());

        modem.show(health.status());
        assertEquals(DeviceStatus.State.ERROR, modem.status().state());
        assertEquals("the GSM modem cannot send SMS: gammu-smsd is not running (its pid file " + pid + " does not "
                + "exist): SMS cannot go out; alerts go by the other channels", modem.status().detail());

        Files.writeString(pid, ProcessHandle.current().pid() + "\n"); // a live process behind the pid file
        modem.show(health.status());
        assertEquals(DeviceStatus.State.ONLINE, modem.status().state(), modem.status().detail());
        assertEquals("gammu-smsd is running and sends from " + dir.resolve("outbox"), modem.status().detail());

        List<String> statuses = platform.logs.events().stream().filter(e -> e.kind() == EventKind.STATUS)
                .map(EventEntry::message).toList();
        assertEquals(2, statuses.size(), statuses.toString());
        assertTrue(statuses.get(0).contains("ERROR") && statuses.get(0).contains("gammu-smsd is not running"),
                statuses.get(0));
        assertTrue(statuses.get(1).contains("ONLINE"), statuses.get(1));
        assertEquals(ModemDevice.TYPE, modem.type());
    }
}
