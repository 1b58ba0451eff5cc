package org.tinysep.simulator.person;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;

/** The person node's parts: SisFall reader, resampling and clipping, the node's rule, the radio budget. */
class PersonNodeTest {

    @TempDir
    Path dir;

    @Test
    void readsSisfallCountsAsMilliG() throws IOException {
        Path f = dir.resolve("F01_SA99_R02.txt");
        Files.writeString(f, "  -9,-257, -25,  84, 247,  27,-120,-987,  63;\n 256,0,-4096,0,0,0,0,0,0;\n",
                StandardCharsets.US_ASCII);
        SisfallRecording r = SisfallRecording.read(f);
        assertEquals("F01", r.code());
        assertEquals("SA99", r.subject());
        assertEquals("R02", r.trial());
        assertTrue(r.isFall());
        assertEquals(2, r.size());
        assertEquals(-1004, r.y()[0], "-257 counts × 3.90625 mg");
        assertEquals(1000, r.x()[1]);
        assertEquals(-16000, r.z()[1], "the ADXL345's -16 g");
        assertEquals(1, r.peakIndex());
    }

    @Test
    void badLinesAreSaidWithFileAndLine() throws IOException {
        Path f = dir.resolve("D01_SA99_R01.txt");
        Files.writeString(f, "1,2,3,4,5,6,7,8,9;\n1,2,3;\n", StandardCharsets.US_ASCII);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SisfallRecording.read(f));
        assertTrue(e.getMessage().contains("line 2: 3 columns"), e.getMessage());
        Path g = dir.resolve("D01_SA99_R03.txt");
        Files.writeString(g, "1,x,3,4,5,6,7,8,9;\n", StandardCharsets.US_ASCII);
        e = assertThrows(IllegalArgumentException.class, () -> SisfallRecording.read(g));
        assertTrue(e.getMessage().contains("'x' is not a whole number"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> SisfallRecording.read(dir.resolve("walk.txt")));
    }

    @Test
    void resamplesToFiftyHertzAndClipsToSixG() {
        int[] x = {1000, 3000, 1000, 3000, 20_000, 20_000, 0, 0};
        SisfallRecording r = new SisfallRecording("D01", "SA99", "R01", x, new int[8], new int[8]);
        List<Acceleration> node = NodeResampler.toNode(r);
        assertEquals(2, node.size(), "8 samples at 200 Hz are 2 at 50 Hz");
        assertEquals(2000, node.get(0).xMg());
        assertEquals(3000, node.get(1).xMg(), "(6000 + 6000 + 0 + 0) / 4: each sample clipped to 6 g first");
    }

    @Test
    void summarisesEveryTwoSecondsAndSendsABurstAroundATrigger() {
        List<MovementSummary> summaries = new ArrayList<>();
        List<Instant> summaryTimes = new ArrayList<>();
        List<AccelerationBurst> bursts = new ArrayList<>();
        List<Instant> burstTimes = new ArrayList<>();
        PersonNodeRule rule = new PersonNodeRule(new PersonNodeRule.Output() {
            @Override
            public void summary(Instant at, MovementSummary s) {
                summaries.add(s);
                summaryTimes.add(at);
            }

            @Override
            public void burst(Instant at, AccelerationBurst b) {
                bursts.add(b);
                burstTimes.add(at);
            }
        });
        Instant t0 = Instant.parse("2026-01-01T00:00:00Z");
        for (int i = 0; i < 500; i++) { // 10 s; one sample of 3 g at 3 s, one of 2.5 g at 3.5 s (same burst)
            Acceleration a = i == 150 ? new Acceleration(0, -3000, 0)
                    : i == 175 ? new Acceleration(0, -2500, 0) : new Acceleration(0, -1000, 0);
            rule.sample(t0.plusMillis(20L * i), a);
        }
        assertEquals(5, summaries.size());
        assertEquals(t0.plusMillis(1980), summaryTimes.get(0), "complete with its 100th sample");
        assertEquals(Duration.ofSeconds(2), summaries.get(0).span());
        assertEquals(new Acceleration(0, -1000, 0), summaries.get(0).mean());
        assertEquals(0, summaries.get(0).magnitudeSdMg());
        assertEquals(3000, summaries.get(1).peakMg());
        assertTrue(summaries.get(1).magnitudeSdMg() > 100, "an impact moves the SD");
        assertEquals(1, bursts.size(), "the second peak falls inside the first burst");
        AccelerationBurst b = bursts.get(0);
        assertEquals(t0.plusMillis(3000), b.trigger());
        assertEquals(150, b.samples().size());
        assertEquals(50, b.samplesBeforeTrigger());
        assertEquals(-3000, b.samples().get(50).yMg());
        assertEquals(t0.plusMillis(3000 + 99 * 20), burstTimes.get(0), "sent when its last sample is taken");
    }

    @Test
    void radioBudgetCountsFramesAndBytesAsTheProtocolDocumentSays() {
        RadioBudget b = new RadioBudget();
        for (int i = 0; i < 1800; i++) {
            b.summary();
        }
        b.recorded(Duration.ofHours(1));
        assertEquals(1800, b.frames());
        assertEquals(46_800, b.bytes(), "sunspot.md: resting, 46 800 bytes per hour");
        b.burst(150);
        assertEquals(1805, b.frames());
        assertEquals(46_800 + 1000, b.bytes(), "sunspot.md: a standard burst is 1000 bytes in 5 frames");
    }

    @Test
    void syntheticRecordingsReadBackAsSisfall() throws IOException {
        SyntheticRecordings.write(dir, "SX01", 7);
        SisfallRecording fall = SisfallRecording.read(dir.resolve("SX01/F01_SX01_R01.txt.gz"));
        assertEquals(15 * 200, fall.size());
        int peak = fall.peakIndex();
        double g = Math.sqrt(Math.pow(fall.x()[peak], 2) + Math.pow(fall.y()[peak], 2) + Math.pow(fall.z()[peak], 2));
        assertTrue(g > 3000, "the synthetic fall has an impact: " + g);
        assertEquals(SyntheticRecordings.CODES.size(), Files.list(dir.resolve("SX01")).count());
    }
}
