package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;

/** Asks the web console's port over HTTP until it answers (issue 29: the first request starts the console). */
final class WebConsoleProbe {

    /** The bound after the banner: as long as the launcher waits for the console before it says it did not start. */
    static final Duration BOUND = WebConsoleLine.WAIT;

    private WebConsoleProbe() {
    }

    /** @return {@link System#nanoTime()} of the first HTTP answer (any status) from 127.0.0.1:port */
    static long awaitAnswer(int port, Duration timeout) throws InterruptedException {
        HttpClient client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(2)).build();
        HttpRequest request = HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/"))
                .timeout(Duration.ofSeconds(5)).GET().build();
        long end = System.nanoTime() + timeout.toNanos();
        String last = "no answer";
        while (System.nanoTime() < end) {
            try {
                HttpResponse<Void> r = client.send(request, HttpResponse.BodyHandlers.discarding());
                if (r.statusCode() > 0) {
                    return System.nanoTime();
                }
            } catch (IOException e) {
                last = e.toString();
            }
            Thread.sleep(20);
        }
        fail("the web console on 127.0.0.1:" + port + " did not answer within " + timeout.toSeconds() + " s: " + last);
        return -1;
    }

    /** @return whether anything accepts a TCP connection on 127.0.0.1:port */
    static boolean listening(int port) {
        try (java.net.Socket s = new java.net.Socket()) {
            s.connect(new java.net.InetSocketAddress("127.0.0.1", port), 1000);
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
