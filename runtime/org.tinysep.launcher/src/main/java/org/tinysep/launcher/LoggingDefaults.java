package org.tinysep.launcher;

import java.util.Locale;
import java.util.Map;
import java.util.logging.Level;
import java.util.logging.Logger;

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

    /**
     * SPI Fly logs through java.util.logging, one INFO line per service provider it registers (a dozen JAXB
     * plug-ins at every start): only its warnings reach the console, unless
     * {@code -Dorg.slf4j.simpleLogger.log.org.apache.aries.spifly=info} (or a {@code java.util.logging} config file) asks for more.
     */
    static final String SPIFLY = "org.apache.aries.spifly";
    /** java.util.logging keeps loggers weakly: this reference keeps SPI Fly's level set (made after the format is). */
    private static Logger spiflyLogger;

    private LoggingDefaults() {
    }

    /** Sets every default that is not already a system property. */
    public static synchronized void apply() {
        DEFAULTS.forEach((key, value) -> {
            if (System.getProperty(key) == null) {
                System.setProperty(key, value);
            }
        });
        if (System.getProperty("java.util.logging.config.file") == null) {
            spiflyLogger = Logger.getLogger(SPIFLY);
            spiflyLogger.setLevel(julLevel(System.getProperty("org.slf4j.simpleLogger.log." + SPIFLY, "warn")));
        }
    }

    /** @return the java.util.logging level of an SLF4J simple-logger level name (warn when unknown) */
    static Level julLevel(String slf4jLevel) {
        return switch (slf4jLevel.strip().toLowerCase(Locale.ROOT)) {
            case "trace" -> Level.FINEST;
            case "debug" -> Level.FINE;
            case "info" -> Level.INFO;
            case "error" -> Level.SEVERE;
            case "off" -> Level.OFF;
            default -> Level.WARNING;
        };
    }
}
