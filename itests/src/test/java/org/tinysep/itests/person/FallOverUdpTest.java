package org.tinysep.itests.person;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.itests.LockStepTestSupport;
import org.tinysep.itests.TestSyncKey;
import org.tinysep.simulator.person.NodeResampler;
import org.tinysep.simulator.person.PersonNodeFrames;
import org.tinysep.simulator.person.PersonNodePlayer;
import org.tinysep.simulator.person.SisfallRecording;
import org.tinysep.simulator.person.SyntheticRecordings;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.sunspot.protocol.SunSpotAddress;

/**
 * Issue 26, items 1 and 3 end to end: the simulator plays recordings (synthetic, in SisFall's format) as a person
 * node's Sun SPOT frames over UDP on 127.0.0.1 in lock-step time; the real Sun SPOT bus radio, Sun SPOT Person
 * abstraction, Fall Detection and alert service run in Felix. Jumps raise nothing; the fall raises one FALL alert
 * that explains itself, within seconds of the impact in platform time.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class FallOverUdpTest extends LockStepTestSupport {

    private static final SunSpotAddress NODE = SunSpotAddress.parse("0014.4F01.0000.F001");

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts", "org.tinysep.sunspot.person",
                "org.tinysep.falldetection");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.alerts", Map.of("contacts", "carer@care.test", "summaryTime", "", "timeZone", "UTC"));
        configs.put("org.tinysep.falldetection", Map.of("timeZone", "UTC"));
        return configs;
    }

    @Test
    public void jumpsRaiseNothingAndAFallRaisesOneFallAlertInWords() throws Exception {
        AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
        Path dir = Files.createTempDirectory("falls");
        SyntheticRecordings.write(dir, "SX01", 5);
        try (SyncClient sync = new SyncClient(new InetSocketAddress(InetAddress.getLoopbackAddress(), syncPort()),
                5000, SyncClient.readKey(TestSyncKey.file()));
                PersonNodePlayer player = new PersonNodePlayer(new InetSocketAddress(InetAddress.getLoopbackAddress(),
                        udpPortOf("BusRadioSunSpot")))) {
            Instant t = sync.hello().platformTime().truncatedTo(ChronoUnit.SECONDS).plusSeconds(60);
            // the node is switched on standing still: its first frames make the bus radio and Sun SPOT Person add it
            List<Acceleration> still = new ArrayList<>();
            for (int i = 0; i < 10 * 50; i++) {
                still.add(new Acceleration(0, -1000, 0));
            }
            player.play(sync, PersonNodeFrames.of(NODE, t, still), t.plusSeconds(10), 20_000_000);
            awaitService(PersonNodeProvider.class, null, TIMEOUT);
            t = t.plusSeconds(20);
            t = play(sync, player, dir.resolve("SX01/D19_SX01_R01.txt.gz"), t);
            assertTrue("no alert after jumps: " + alerts.open(), alerts.open().stream()
                    .noneMatch(a -> a.kind() == AlertKind.FALL));
            SisfallRecording fall = SisfallRecording.read(dir.resolve("SX01/F01_SX01_R01.txt.gz"));
            Instant impact = t.plusMillis(1000L * fall.peakIndex() / SisfallRecording.RATE_HZ);
            play(sync, player, dir.resolve("SX01/F01_SX01_R01.txt.gz"), t);
            await(TIMEOUT, () -> alerts.open().stream().anyMatch(a -> a.kind() == AlertKind.FALL), "a FALL alert");
            List<Alert> falls = alerts.open().stream().filter(a -> a.kind() == AlertKind.FALL).toList();
            assertEquals("one FALL alert: " + falls, 1, falls.size());
            Alert a = falls.get(0);
            assertTrue(a.subject(), a.subject().startsWith("Fall: the person wearing the node fell at "));
            assertTrue(a.text(), a.text().contains("a hard impact (") && a.text().contains("then lying still for")
                    && a.text().contains("the body turned by") && a.text().contains("(node 0014.4F01.0000.F001)"));
            // no room sensor in this platform: the alert says so rather than naming a room
            assertTrue(a.text(), a.text().contains("; no room seen yet (no room sensor has reported activity"));
            long delay = a.raisedAt().getEpochSecond() - impact.getEpochSecond();
            assertTrue("raised " + delay + " s after the impact (platform time)", delay >= 0 && delay <= 15);
        }
    }

    /** Plays one recording plus 20 s of its last posture from {@code t}; @return when the next one may start */
    private static Instant play(SyncClient sync, PersonNodePlayer player, Path file, Instant t) throws Exception {
        SisfallRecording r = SisfallRecording.read(file);
        List<Acceleration> samples = new ArrayList<>(NodeResampler.toNode(r));
        Acceleration last = samples.get(samples.size() - 1);
        for (int i = 0; i < 20 * 50; i++) {
            samples.add(last);
        }
        Instant end = t.plusMillis(20L * samples.size());
        player.play(sync, PersonNodeFrames.of(NODE, t, samples), end, 20_000_000);
        return end.truncatedTo(ChronoUnit.SECONDS).plusSeconds(2);
    }
}
