package org.tinysep.sunspot.person.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.ButtonAction;
import org.tinysep.api.sensor.person.ButtonEvent;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.device.support.testing.FakeSunSpotBus;
import org.tinysep.device.support.testing.TestPlatform;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.ButtonReport;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/** Person node payloads in (as the bus radio hands them over), listener calls and event-log entries out. */
class SunSpotPersonDeviceTest {

    private static final Instant T0 = TestPlatform.T0;
    private final TestPlatform platform = new TestPlatform();
    private final List<Object> heard = new ArrayList<>();

    private SunSpotPersonDevice device(String... types) {
        SunSpotPersonDevice d = new SunSpotPersonDevice(platform.context(SunSpotPersonDriver.NAME),
                new FakeSunSpotBus(types));
        d.connect(new PersonNodeListener() {
            @Override
            public void movementSummarised(PersonNodeProvider source, MovementSummary summary) {
                heard.add(summary);
            }

            @Override
            public void burstReceived(PersonNodeProvider source, AccelerationBurst burst) {
                heard.add(burst);
            }

            @Override
            public void buttonChanged(PersonNodeProvider source, ButtonEvent event) {
                heard.add(event);
            }
        });
        return d;
    }

    private static void deliver(SunSpotPersonDevice d, Object payload, long millis) {
        d.payloadReceived(null, 6, SunSpotPayloads.encode((org.tinysep.sunspot.protocol.SunSpotPayload) payload),
                T0.plusMillis(millis));
    }

    private List<String> events() {
        return platform.logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT)
                .map(EventEntry::message).toList();
    }

    private static String parameter(SunSpotPersonDevice d, String key) {
        return d.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }

    private static List<AccelerationSample> samples(int n) {
        List<AccelerationSample> s = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            s.add(new AccelerationSample(i, -1000 + i, 3 * i));
        }
        return s;
    }

    @Test
    void buttonsAndSummariesReachTheListenersWithTheirArrival() {
        SunSpotPersonDevice d = device("person");
        d.setParameter("person", " Anna ");
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(12, -985, 110), 6, 1003), 0);
        deliver(d, new ButtonReport(1, true), 500);
        deliver(d, new ButtonReport(1, false), 1700);

        assertEquals(List.of(new MovementSummary(T0, Duration.ofSeconds(2), new Acceleration(12, -985, 110), 6, 1003),
                new ButtonEvent(1, ButtonAction.PRESSED, T0.plusMillis(500)),
                new ButtonEvent(1, ButtonAction.RELEASED, T0.plusMillis(1700))), heard);
        assertEquals("Anna", d.person().orElseThrow());
        assertEquals(1003, d.lastSummary().orElseThrow().peakMg());
        assertEquals(List.of("worn by Anna", "switch 1 pressed (Anna)", "switch 1 released (Anna)"), events());
    }

    @Test
    void aBurstIsDeliveredOnceCompleteWithTheArrivalOfChunkZeroAsItsTrigger() {
        SunSpotPersonDevice d = device("person");
        List<BurstChunk> chunks = BurstChunk.split(7, 50, 50, samples(150));
        long[] sent = {0, 260, 900, 1540, 1980}; // each chunk leaves with its last sample (docs/protocols/sunspot.md)
        for (int i = 0; i < chunks.size(); i++) {
            assertTrue(heard.isEmpty(), "nothing before the last chunk");
            deliver(d, chunks.get(i), 10_000 + sent[i]);
        }
        assertEquals(1, heard.size());
        AccelerationBurst b = (AccelerationBurst) heard.get(0);
        assertEquals(T0.plusSeconds(10), b.trigger());
        assertEquals(50, b.sampleRateHz());
        assertEquals(50, b.samplesBeforeTrigger());
        assertEquals(150, b.samples().size());
        assertEquals(new Acceleration(149, -851, 447), b.samples().get(149));
        assertEquals("1", parameter(d, "burstsReceived"));
        assertTrue(events().get(0).startsWith("acceleration burst received: 150 samples at 50 Hz"), events().get(0));
    }

    @Test
    void anIncompleteBurstIsGivenUpInWordsWhenOverdueAndAnInconsistentOneAtOnce() {
        SunSpotPersonDevice d = device("person");
        List<BurstChunk> chunks = BurstChunk.split(3, 50, 50, samples(150));
        deliver(d, chunks.get(0), 0);
        deliver(d, chunks.get(1), 300);
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(0, -1000, 0), 5, 1010), 5_000);
        assertEquals("0", parameter(d, "burstsGivenUp"), "5.2 s for a 5-chunk burst at 50 Hz");
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(0, -1000, 0), 5, 1010), 7_000);
        assertEquals("1", parameter(d, "burstsGivenUp"));
        assertEquals("acceleration burst 3 given up: 2 of its 5 chunks arrived, the others did not arrive within "
                + "5.2 s of the first; the movement summaries still tell the posture and stillness after it",
                events().get(0));

        deliver(d, new BurstChunk(4, 0, 2, 50, 10, samples(32)), 8_000);
        deliver(d, new BurstChunk(4, 1, 2, 25, 10, samples(3)), 8_100);
        assertEquals("2", parameter(d, "burstsGivenUp"));
        assertTrue(events().get(1).contains("chunk 1 says 25 Hz, the first said 50 Hz"), events().get(1));
        assertTrue(heard.stream().noneMatch(h -> h instanceof AccelerationBurst));
    }

    @Test
    void aNodeThatAlsoReportsAsARoomSensorRaisesNothingAndSaysWhy() {
        SunSpotPersonDevice d = device("movement", "person");
        deliver(d, new ButtonReport(2, true), 0);
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(0, -1000, 0), 5, 1010), 100);
        assertEquals(List.of(), heard);
        assertEquals("2", parameter(d, "ignoredReports"));
        assertEquals(List.of("switch 2 pressed on a node that also reports as movement: not taken as a person's "
                + "switch, nothing is raised (a person node sends only person reports)"), events());
    }

    @Test
    void badPayloadsAreCountedAndNeverReachAListener() {
        SunSpotPersonDevice d = device("person");
        d.payloadReceived(null, 6, new byte[] {6, 0x11, 3, 1}, T0);
        d.payloadReceived(null, 6, new byte[] {6, 0x31, 1, 0, 1, 50, 0, 0}, T0);
        d.payloadReceived(null, 6, new byte[] {2, 1, 0, 1}, T0);
        d.payloadReceived(null, 2, new byte[] {2, 1, 0, 1}, T0); // another sensor type of the node: not ours
        assertEquals(List.of(), heard);
        assertEquals("3", parameter(d, "rejectedPayloads"));
    }

    @Test
    void theDeviceTellsSinceWhenTheNodeLiesStill() {
        SunSpotPersonDevice d = device("person");
        AccelerationSample flat = new AccelerationSample(0, 0, 1000);
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(100, -900, 300), 240, 1700), 2_000);
        assertEquals("", parameter(d, "stillSince"));
        assertTrue(parameter(d, "state").startsWith("moving"), parameter(d, "state"));
        deliver(d, new MovementSummaryReport(2000, flat, 8, 1010), 4_000);
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(20, -30, 998), 5, 1003), 6_000);
        assertEquals(T0.plusSeconds(2).toString(), parameter(d, "stillSince"), "still from the start of its period");
        assertTrue(parameter(d, "state").startsWith("still since " + T0.plusSeconds(2)), parameter(d, "state"));
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(0, -1000, 0), 6, 1004), 8_000);
        assertEquals(T0.plusSeconds(6).toString(), parameter(d, "stillSince"), "turned over: a new still run");
        deliver(d, new MovementSummaryReport(2000, new AccelerationSample(0, -1000, 0), 31, 1100), 10_000);
        assertEquals("", parameter(d, "stillSince"));
    }

    @Test
    void theWearersNameIsCheckedWhenSet() {
        SunSpotPersonDevice d = device("person");
        try {
            d.setParameter("person", "x".repeat(61));
        } catch (IllegalArgumentException e) {
            assertTrue(e.getMessage().contains("at most 60 characters"), e.getMessage());
        }
        assertTrue(d.person().isEmpty());
    }
}
