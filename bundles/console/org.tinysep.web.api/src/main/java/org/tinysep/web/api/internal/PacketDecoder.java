package org.tinysep.web.api.internal;

import java.util.concurrent.atomic.AtomicLong;

/**
 * The decoded form of a logged packet, made by the protocol bundles' own decoders ({@code org.tinysep.amica.protocol},
 * {@code org.tinysep.sunspot.protocol}), imported dynamically: the console starts before the applications (and so
 * before the protocol libraries) and keeps working without them (no decoded form then). A protocol is only touched
 * once its package can be loaded; a missing one is looked for again at most every 10 s.
 */
final class PacketDecoder {

    private static final long RETRY_NANOS = 10_000_000_000L;
    private static final Protocol AMICA = new Protocol("org.tinysep.amica.protocol.AmicaCodec");
    private static final Protocol SUN_SPOT = new Protocol("org.tinysep.sunspot.protocol.SunSpotCodec");

    private PacketDecoder() {
    }

    /** @return e.g. {@code "AmICA 1.17 → 1.0 #6: motion detected"}, or empty when no protocol decodes the bytes */
    static String decode(String origin, byte[] bytes) {
        boolean sunSpotFirst = origin.contains("SunSpot") || origin.matches("(?i).*node [0-9a-f]{4}\\..*");
        String first = sunSpotFirst ? sunSpot(bytes) : amica(bytes);
        if (!first.isEmpty()) {
            return first;
        }
        return sunSpotFirst ? amica(bytes) : sunSpot(bytes);
    }

    private static String amica(byte[] bytes) {
        try {
            return AMICA.available() ? AmicaText.of(bytes) : "";
        } catch (LinkageError | RuntimeException e) {
            return "";
        }
    }

    private static String sunSpot(byte[] bytes) {
        try {
            return SUN_SPOT.available() ? SunSpotText.of(bytes) : "";
        } catch (LinkageError | RuntimeException e) {
            return "";
        }
    }

    /** A protocol library, looked up through this bundle's class loader (DynamicImport-Package). */
    private static final class Protocol {
        private final String probe;
        private volatile boolean found;
        private final AtomicLong lastTry = new AtomicLong(System.nanoTime() - 2 * RETRY_NANOS);

        Protocol(String probe) {
            this.probe = probe;
        }

        boolean available() {
            if (found) {
                return true;
            }
            long now = System.nanoTime();
            long last = lastTry.get();
            if (now - last < RETRY_NANOS || !lastTry.compareAndSet(last, now)) {
                return false;
            }
            try {
                Class.forName(probe, false, PacketDecoder.class.getClassLoader());
                found = true;
            } catch (ClassNotFoundException | LinkageError e) {
                found = false;
            }
            return found;
        }
    }
}
