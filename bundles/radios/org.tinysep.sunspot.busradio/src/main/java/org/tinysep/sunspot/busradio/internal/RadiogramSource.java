package org.tinysep.sunspot.busradio.internal;

import java.io.IOException;

/**
 * The narrow seam between the bus radio and the Sun SPOT SDK: a source of radiograms on one radiogram port. The
 * SDK-backed implementation ({@link CldcRadiogramSource}) is the only class that touches
 * {@code javax.microedition.io}; tests use an in-process fake.
 */
interface RadiogramSource extends AutoCloseable {

    /** Opens a source on a radiogram port. */
    interface Opener {
        /**
         * @param port the radiogram port, e.g. 100 for {@code radiogram://:100}
         * @throws SdkUnavailableException if the SDK is not installed (no classes, no radiogram protocol)
         * @throws IOException             if the SDK is there but the port cannot be opened (e.g. no basestation)
         */
        RadiogramSource open(int port) throws SdkUnavailableException, IOException;
    }

    /**
     * Blocks until the next radiogram arrives.
     *
     * @throws IOException when the connection failed or was closed
     */
    Radiogram receive() throws IOException;

    /** Closes the connection; a blocked {@link #receive()} then ends with an IOException. Never throws. */
    @Override
    void close();
}
