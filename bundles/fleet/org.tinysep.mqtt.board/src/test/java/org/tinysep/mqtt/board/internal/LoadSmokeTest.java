package org.tinysep.mqtt.board.internal;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.mqtt.Mosquitto;

/**
 * The load test's short version in the normal suite (a few flats, a few seconds): it runs, the board tracks every
 * flat and the report has every figure. It asserts no figures (the machine is shared); the full run is
 * {@code mqtt-load/run.sh} (200 flats: the same test with {@code -Dload.flats=200} etc.), its figures in docs/central-board.md.
 */
class LoadSmokeTest {

    @Test
    void runsAndReports() throws Exception {
        assumeTrue(Mosquitto.isInstalled(), "Debian's mosquitto is not installed (scripts/install-deps.sh)");
        int flats = Integer.getInteger("load.flats", 5);
        int seconds = Integer.getInteger("load.seconds", 8);
        Path report = Path.of("target", "mqtt-load-report.txt");
        Files.deleteIfExists(report);
        LoadHarness.Options options = new LoadHarness.Options(flats, seconds, Integer.getInteger("load.heartbeatSeconds", 2),
                Integer.getInteger("load.stateMillis", 1000), Integer.getInteger("load.alertSeconds", 3),
                Integer.getInteger("load.occupancySeconds", 4));
        String text = new LoadHarness(options).run(report);
        System.out.println(text);
        assertTrue(text.contains("flats seen=" + flats), text);
        for (String figure : new String[] {"alert latency flat→board: p50=", "lost=", "CPU (% of one core): broker=",
            "peak RSS MB: broker=", "per flat"}) {
            assertTrue(text.contains(figure), figure + " missing in\n" + text);
        }
        assertTrue(Files.readString(report).equals(text));
    }
}
