package org.tinysep.itests.aal;

import java.io.IOException;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.itests.AmicaNode;

/**
 * A simulated AmICA simple-light node that behaves like the hardware: it answers every Light Control command with
 * a status frame reporting the new value (so the platform's request is confirmed), and writes what it received
 * to a shared log as {@code HH:mm:ss <label> on|off} at the platform's (virtual) time of receipt.
 */
final class SimulatedLight implements AutoCloseable {

    private final String label;
    private final AmicaNode node;
    private final Supplier<Instant> clock;
    private final List<String> log;
    private final ExecutorService executor = Executors.newSingleThreadExecutor(r -> new Thread(r, "light-node"));
    private volatile boolean running = true;

    SimulatedLight(String label, AmicaNode node, Supplier<Instant> clock, List<String> log) {
        this.label = label;
        this.node = node;
        this.clock = clock;
        this.log = log;
    }

    String label() {
        return label;
    }

    AmicaNode node() {
        return node;
    }

    /** Reports the light off once (its periodic status), then answers commands until closed. */
    SimulatedLight start() throws IOException {
        node.send(new LightControl(0));
        executor.execute(this::serve);
        return this;
    }

    private void serve() {
        while (running) {
            byte[] payload;
            try {
                payload = node.receivePayload();
            } catch (AssertionError quietFor5Seconds) {
                continue;
            } catch (Exception closed) {
                return;
            }
            Instant at = clock.get();
            try {
                AmicaPayload p = AmicaPayloads.decode(payload);
                if (p instanceof LightControl c) {
                    log.add(VirtualFlat.hms(at) + " " + label + " " + VirtualFlat.onOff(c.percent() > 0));
                    node.send(new LightControl(c.percent()));
                } else {
                    log.add(VirtualFlat.hms(at) + " " + label + " unexpected " + p);
                }
            } catch (AmicaProtocolException | IOException e) {
                log.add(VirtualFlat.hms(at) + " " + label + " failed: " + e);
            }
        }
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        node.close();
        executor.shutdownNow();
        executor.awaitTermination(5, TimeUnit.SECONDS);
    }
}
