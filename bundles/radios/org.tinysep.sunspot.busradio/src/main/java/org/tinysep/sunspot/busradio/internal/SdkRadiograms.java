package org.tinysep.sunspot.busradio.internal;

import java.io.IOException;

/**
 * Opens radiogram sources through the Sun SPOT SDK, if it is there. Refers to {@link CldcRadiogramSource} only
 * inside {@link #open(int)}, so this class loads without the SDK; a missing {@code javax.microedition.io} shows
 * up as a {@link LinkageError} at that call and becomes an {@link SdkUnavailableException}.
 */
final class SdkRadiograms {

    /** The opener the driver uses. */
    static final RadiogramSource.Opener OPENER = SdkRadiograms::open;

    private SdkRadiograms() {
    }

    static RadiogramSource open(int port) throws SdkUnavailableException, IOException {
        try {
            return CldcRadiogramSource.open(port);
        } catch (LinkageError e) { // NoClassDefFoundError: javax.microedition.io is not wired to this bundle
            throw new SdkUnavailableException("javax.microedition.io is missing: " + e.getClass().getSimpleName() + " "
                    + e.getMessage());
        }
    }
}
