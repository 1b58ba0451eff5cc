package org.tinysep.timecontroller.internal;

/**
 * The Gogo command {@code tinysep:time [real|external]}: shows the platform time, the clock mode and the
 * synchroniser link; with an argument switches the mode first (stored in ConfigAdmin, so a restart keeps it).
 * Errors are one-line {@link IllegalArgumentException}s.
 */
public final class TimeCommands {

    private final TimeControllerDriver driver;

    TimeCommands(TimeControllerDriver driver) {
        this.driver = driver;
    }

    /** {@code time}: now, mode and the synchroniser's port. */
    public String time() {
        ClockService clock = driver.clock();
        return "now        " + clock.now() + "\nmode       " + clock.mode() + "\nsync port  " + driver.syncPort()
                + " (" + driver.linkState() + ")\nsync key   " + driver.keyFile()
                + " (the synchroniser signs its TICKs with it: docs/time-sync.md)";
    }

    /** {@code time real|external}: switches, then shows the state. */
    public String time(String mode) {
        driver.request(Modes.parse(mode));
        return time();
    }
}
