package org.tinysep.simulator.person;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.simulator.time.FakeSynchroniserPeer;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/** A recorded fall played as the person node's frames over UDP on 127.0.0.1, in lock-step with a fake platform. */
class PersonNodePlayerTest {

    private static final SunSpotAddress NODE = SunSpotAddress.parse("0014.4F01.0000.A001");

    @TempDir
    Path dir;

    @Test
    void aFallIsSentAsSummariesAndAChunkedBurstEachAtItsOwnInstant() throws Exception {
        SyntheticRecordings.write(dir, "SX01", 3);
        SisfallRecording fall = SisfallRecording.read(dir.resolve("SX01/F01_SX01_R01.txt.gz"));
        Instant start = Instant.parse("2026-11-23T08:00:00Z");
        List<PersonNodeFrames.Timed> frames = PersonNodeFrames.of(NODE, start, NodeResampler.toNode(fall));
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL");
                SyncClient sync = new SyncClient(peer.address(), 2000);
                DatagramChannel radio = DatagramChannel.open()
                        .bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
                PersonNodePlayer player = new PersonNodePlayer((InetSocketAddress) radio.getLocalAddress())) {
            sync.hello();
            int sent = player.play(sync, frames, start.plusSeconds(20), 0);
            assertEquals(frames.size(), sent);
            List<SunSpotPayload> received = new ArrayList<>();
            radio.configureBlocking(true);
            ByteBuffer buf = ByteBuffer.allocate(2048);
            for (int i = 0; i < sent; i++) {
                buf.clear();
                radio.receive(buf);
                SunSpotFrame f = SunSpotCodec.decode(Arrays.copyOf(buf.array(), buf.position()), 0, buf.position());
                assertEquals(NODE, f.source());
                received.add(SunSpotPayloads.decode(f.payload()));
            }
            long summaries = received.stream().filter(MovementSummaryReport.class::isInstance).count();
            List<BurstChunk> chunks = received.stream().filter(BurstChunk.class::isInstance)
                    .map(BurstChunk.class::cast).toList();
            assertEquals(7, summaries, "15 s of 50 Hz samples: a summary every 2 s");
            assertEquals(5, chunks.size(), "one burst, 150 samples in 5 chunks: " + chunks);
            assertEquals(List.of(0, 1, 2, 3, 4), chunks.stream().map(BurstChunk::chunkIndex).toList());
            assertEquals(50, chunks.get(0).samplesBeforeTrigger());
            Instant trigger = frames.stream().filter(t -> t.payload() instanceof BurstChunk c && c.chunkIndex() == 0)
                    .findFirst().orElseThrow().at();
            assertTrue(!trigger.isBefore(start.plusSeconds(4)) && trigger.isBefore(start.plusSeconds(5)),
                    "chunk 0 leaves at the trigger, 4.4 s in: " + trigger);
            Instant lastChunk = frames.stream().filter(t -> t.payload() instanceof BurstChunk c && c.last())
                    .findFirst().orElseThrow().at();
            assertEquals(1980, lastChunk.toEpochMilli() - trigger.toEpochMilli(), "the last chunk 2 s later");
            List<Instant> ticks = peer.ticks();
            assertEquals(start.plusMillis(1980), ticks.get(0), "the first summary leaves at 1.98 s: the platform is "
                    + "TICKed to that instant, milliseconds kept, so the radio stamps it 1.98 s, not 1 s");
            assertTrue(trigger.getNano() != 0, "the trigger lies inside a second: " + trigger);
            assertTrue(ticks.contains(trigger), "TICKed to the trigger itself, not its whole second: " + ticks);
            assertEquals(frames.stream().map(PersonNodeFrames.Timed::at).distinct().toList(),
                    ticks.subList(0, ticks.size() - 1), "one TICK per instant with frames, each as it is");
            assertEquals(start.plusSeconds(20), ticks.get(ticks.size() - 1), "played up to the end");
            assertInstanceOf(MovementSummaryReport.class, received.get(0));
        }
    }
}
