package org.tinysep.mqtt.board.loadtest;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * The simulated flats' process (started by {@link LoadHarness} so that their CPU and memory are measured apart from
 * the board's): {@code SimFlats <brokerUrl> <prefix> <flats> <seconds> <heartbeatS> <stateMs> <alertS> <occupancyS>}.
 * Prints {@code READY} once every flat is connected and {@code SIMSTATS k=v …} at the end, then waits for its
 * standard input to close (so that the harness can read its CPU time) and ends.
 */
public final class SimFlats {

    private SimFlats() {
    }

    public static void main(String[] a) throws Exception {
        String url = a[0];
        String prefix = a[1];
        int flats = Integer.parseInt(a[2]);
        int seconds = Integer.parseInt(a[3]);
        SimFlat.Rates rates = new SimFlat.Rates(Integer.parseInt(a[4]), Integer.parseInt(a[5]), Integer.parseInt(a[6]),
                Integer.parseInt(a[7]));
        SimFlat.Stats stats = new SimFlat.Stats();
        ScheduledExecutorService ex = Executors.newScheduledThreadPool(4);
        List<SimFlat> all = new ArrayList<>();
        for (int i = 1; i <= flats; i++) {
            SimFlat f = new SimFlat(url, prefix, String.format("flat%03d", i), rates, stats);
            f.start(ex);
            all.add(f);
        }
        System.out.println("READY " + flats);
        System.out.flush();
        Thread.sleep(seconds * 1000L);
        ex.shutdown();
        ex.awaitTermination(30, TimeUnit.SECONDS);
        Thread.sleep(3000); // the last acknowledgements' answers
        for (SimFlat f : all) {
            f.stop();
        }
        System.out.println("SIMSTATS published=" + stats.published + " bytes=" + stats.bytes + " boardTopics="
                + stats.boardTopics + " failed=" + stats.failed + " alerts=" + stats.alerts + " acks=" + stats.acks);
        System.out.flush();
        System.in.read(); // the harness reads this process's CPU time before letting it end (closes stdin)
        System.exit(0);
    }
}
