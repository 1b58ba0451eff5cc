package org.tinysep.sunspot.busradio.internal;

import java.io.IOException;
import javax.microedition.io.ConnectionNotFoundException;
import javax.microedition.io.Connector;
import javax.microedition.io.Datagram;
import javax.microedition.io.DatagramConnection;

/**
 * Radiograms through the Sun SPOT SDK's CLDC connection API, in-process: {@code Connector.open("radiogram://:" +
 * port)} as a {@link DatagramConnection}. The only class of the bundle that touches {@code javax.microedition.io},
 * which the bundle imports optionally: without the SDK this class cannot even be linked, so nothing refers to it
 * but {@link SdkRadiograms}, which turns that into an {@link SdkUnavailableException}. See
 * {@code docs/sunspot-sdk.md}.
 */
final class CldcRadiogramSource implements RadiogramSource {

    private final DatagramConnection connection;
    private final int maximumLength;

    private CldcRadiogramSource(DatagramConnection connection) throws IOException {
        this.connection = connection;
        this.maximumLength = connection.getMaximumLength();
    }

    static RadiogramSource open(int port) throws SdkUnavailableException, IOException {
        String url = "radiogram://:" + port;
        Object c;
        try {
            c = Connector.open(url);
        } catch (ConnectionNotFoundException e) {
            throw new SdkUnavailableException("no radiogram protocol for " + url + ": " + e.getMessage());
        } catch (Error e) {
            if (e.getClass() != Error.class) {
                throw e;
            }
            // a plain Error comes from a CLDC API stub jar (e.g. "API Stub has been used"), not from the SDK
            throw new SdkUnavailableException("javax.microedition.io is only an API stub: " + e.getMessage());
        }
        if (!(c instanceof DatagramConnection dc)) {
            throw new SdkUnavailableException(url + " opened a " + c.getClass().getName()
                    + ", not a DatagramConnection");
        }
        try {
            return new CldcRadiogramSource(dc);
        } catch (IOException e) {
            dc.close();
            throw e;
        }
    }

    @Override
    public Radiogram receive() throws IOException {
        // a fresh datagram each time: no reliance on how an SDK treats reset() and lengths (a few per second)
        Datagram datagram = connection.newDatagram(maximumLength);
        connection.receive(datagram);
        byte[] data = new byte[datagram.getLength()];
        datagram.readFully(data); // the DataInput view: how Sun SPOT applications read radiograms
        return new Radiogram(datagram.getAddress(), data);
    }

    @Override
    public void close() {
        try {
            connection.close();
        } catch (IOException | RuntimeException e) {
            // closing anyway
        }
    }
}
