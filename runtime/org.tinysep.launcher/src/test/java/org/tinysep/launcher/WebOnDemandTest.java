package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 29, item 3: the web console starts on its first use. The launcher holds the port; the first connection
 * starts the console (here a stand-in server that binds the same address, as Jetty does) and is handed over to it.
 */
class WebOnDemandTest {

    private final AtomicInteger starts = new AtomicInteger();
    private ServerSocket console;
    private WebOnDemand onDemand;

    @AfterEach
    void close() throws IOException {
        if (onDemand != null) {
            onDemand.close();
        }
        if (console != null) {
            console.close();
        }
    }

    @Test
    void theFirstConnectionStartsTheConsoleAndGetsItsAnswer() throws Exception {
        InetSocketAddress address = freeAddress();
        onDemand = WebOnDemand.listen(address, () -> startConsole(address));
        assertFalse(onDemand.started(), "nothing started before anyone connects");
        try (Socket client = new Socket(address.getAddress(), address.getPort())) {
            client.getOutputStream().write("GET / HTTP/1.0\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
            client.shutdownOutput();
            String answer = new String(client.getInputStream().readAllBytes(), StandardCharsets.US_ASCII);
            assertEquals("HTTP/1.0 200 OK\r\n\r\nyou asked: GET / HTTP/1.0", answer);
        }
        assertEquals(1, starts.get());
        assertTrue(onDemand.started());
    }

    @Test
    void startNowFreesThePortAndStartsTheConsoleOnce() throws Exception {
        InetSocketAddress address = freeAddress();
        onDemand = WebOnDemand.listen(address, () -> startConsole(address));
        assertTrue(onDemand.startNow(), "the console serves");
        assertTrue(onDemand.startNow());
        assertEquals(1, starts.get(), "started once");
    }

    @Test
    void aPortHeldByAnotherProgramIsSaid() throws Exception {
        try (ServerSocket other = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            InetSocketAddress address = new InetSocketAddress(other.getInetAddress(), other.getLocalPort());
            assertThrows(IOException.class, () -> WebOnDemand.listen(address, () -> true));
        }
    }

    /** Binds the address the launcher gave up and answers each connection with what it was asked. */
    private boolean startConsole(InetSocketAddress address) {
        starts.incrementAndGet();
        try {
            console = new ServerSocket();
            console.setReuseAddress(true);
            console.bind(address);
        } catch (IOException e) {
            throw new IllegalStateException("the port was not given up: " + e, e);
        }
        Thread serve = new Thread(() -> {
            try (Socket s = console.accept(); InputStream in = s.getInputStream(); OutputStream out = s.getOutputStream()) {
                String request = new String(in.readAllBytes(), StandardCharsets.US_ASCII).strip();
                out.write(("HTTP/1.0 200 OK\r\n\r\nyou asked: " + request).getBytes(StandardCharsets.US_ASCII));
            } catch (IOException ignored) {
                // the test closed it
            }
        });
        serve.setDaemon(true);
        serve.start();
        return true;
    }

    private static InetSocketAddress freeAddress() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            return new InetSocketAddress(s.getInetAddress(), s.getLocalPort());
        }
    }
}
