package org.tinysep.launcher;

import java.util.Map;

/**
 * SLF4J simple-logger (and java.util.logging one-line format) settings, applied as system properties before the first logger is created. They hold
 * for the launcher and for every bundle (slf4j-simple reads system properties). A value given on the command
 * line ({@code java -Dorg.slf4j.simpleLogger.defaultLogLevel=debug -jar tinysep.jar}) wins.
 */
public final class LoggingDefaults {

    /** The defaults: INFO, date and time, short logger names. */
    public static final Map<String, String> DEFAULTS = Map.of(
            "org.slf4j.simpleLogger.defaultLogLevel", "info",
            "org.slf4j.simpleLogger.showDateTime", "true",
            "org.slf4j.simpleLogger.dateTimeFormat", "yyyy-MM-dd HH:mm:ss.SSS",
            "org.slf4j.simpleLogger.showShortLogName", "true",
            // bundles that log through java.util.logging (e.g. SPI Fly) get one line in a similar shape
            "java.util.logging.SimpleFormatter.format", "%1$tF %1$tT.%1$tL [%3$s] %4$s - %5$s%6$s%n");

    private LoggingDefaults() {
    }

    /** Sets every default that is not already a system property. */
    public static void apply() {
        DEFAULTS.forEach((key, value) -> {
            if (System.getProperty(key) == null) {
                System.setProperty(key, value);
            }
        });
    }
}
