package org.tinysep.simulator.cli;

import java.time.LocalDate;
import org.tinysep.tools.cli.Cli;

/** The command line, parsed and checked ({@link Flags}). */
record Options(String flat, String scenario, String target, int amicaPort, int sunSpotPort, int syncPort,
        double speed, boolean lockstep, long seed, int fromSecond, int untilSecond, LocalDate date,
        int progressMinutes, int paceMillis, int jitter, double wander, String replay, String mapping,
        boolean fullRate, String syncKey, boolean releaseClock, int waitSeconds, java.time.LocalDateTime end,
        boolean noPendant) {

    /**
     * @param args the command line ({@link Flags}: every option, its default and its check)
     * @throws IllegalArgumentException naming an unknown option, a bad value or a stray argument
     */
    static Options parse(String[] args) {
        return Cli.parse(new Flags(), args).options();
    }

    /** @return the synchroniser key of {@code --sync-key}, or null without the option */
    byte[] syncKeyBytes() throws java.io.IOException {
        if (syncKey == null) {
            return null;
        }
        try {
            return org.tinysep.simulator.time.SyncClient.readKey(java.nio.file.Path.of(syncKey));
        } catch (java.io.IOException e) {
            throw new java.io.IOException("--sync-key " + syncKey + ": cannot read the platform's synchroniser key ("
                    + e + ")", e);
        }
    }
}
