package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;

/**
 * Issue 25, item 5, over real HTTP: a live stream ends when its login session ends (logout, a password change),
 * and one user cannot take every stream slot: at most 4 per login, the caregivers together 12, the installer
 * always gets one.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebStreamsTest extends WebTestSupport {

    /** Long enough for any machine; the stream checks its session every second. Without the check it never ends. */
    private static final long ENDS_WITHIN_S = 10;

    /** One reader per open stream (the common pool may have a single thread on a small machine). */
    private final ExecutorService readers = Executors.newCachedThreadPool();

    @Before
    public void passwords() {
        setPasswords();
    }

    @After
    public void stopReaders() {
        readers.shutdownNow();
    }

    @Test
    public void aStreamEndsWhenItsSessionEnds() throws Exception {
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        CompletableFuture<String> stream = read(open(caregiver, 200));
        HttpResponse<String> logout = call("DELETE", "/api/session", null, caregiver, true);
        assertEquals(logout.body(), 200, logout.statusCode());
        String text = endsWithin(stream, "after DELETE /api/session");
        assertTrue(text, text.contains("event: ended"));

        Login again = login("caregiver", CAREGIVER_PASSWORD);
        CompletableFuture<String> second = read(open(again, 200));
        shell("tinysep:web-password caregiver " + CAREGIVER_PASSWORD); // a password change ends every session
        text = endsWithin(second, "after tinysep:web-password");
        assertTrue(text, text.contains("the login session ended"));
        assertEquals(401, call("GET", "/api/stream/events", null, again, false).statusCode());
    }

    @Test
    public void oneUserCannotTakeEveryStreamSlot() throws Exception {
        List<CompletableFuture<String>> open = new ArrayList<>();
        Login first = login("caregiver", CAREGIVER_PASSWORD);
        for (int i = 0; i < 4; i++) {
            open.add(read(open(first, 200)));
        }
        HttpResponse<InputStream> fifth = open(first, 503);
        String refusal = new String(fifth.body().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(refusal, refusal.contains("this login already has 4 live streams"));
        for (int login = 0; login < 2; login++) {
            Login more = login("caregiver", CAREGIVER_PASSWORD);
            for (int i = 0; i < 4; i++) {
                open.add(read(open(more, 200)));
            }
        }
        HttpResponse<InputStream> thirteenth = open(login("caregiver", CAREGIVER_PASSWORD), 503);
        refusal = new String(thirteenth.body().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(refusal, refusal.contains("kept for the installer"));
        open.add(read(open(login("installer", INSTALLER_PASSWORD), 200))); // was 503 when one user held all 16
        shell("tinysep:web-password caregiver " + CAREGIVER_PASSWORD); // ends every session, so every stream
        for (CompletableFuture<String> s : open) {
            endsWithin(s, "after the password change");
        }
    }

    private HttpResponse<InputStream> open(Login login, int expected) throws IOException, InterruptedException {
        HttpRequest request = HttpRequest.newBuilder(URI.create(base() + "/api/stream/events"))
                .header("Cookie", login.cookie()).GET().build();
        HttpResponse<InputStream> r = http.send(request, HttpResponse.BodyHandlers.ofInputStream());
        assertEquals(expected, r.statusCode());
        return r;
    }

    /** @return the stream's whole text, once the server ends it */
    private CompletableFuture<String> read(HttpResponse<InputStream> stream) {
        return CompletableFuture.supplyAsync(() -> {
            try (InputStream in = stream.body()) {
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }, readers);
    }

    private static String endsWithin(CompletableFuture<String> stream, String when) throws Exception {
        try {
            return stream.get(ENDS_WITHIN_S, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            throw new AssertionError("the live stream was still open " + ENDS_WITHIN_S + " s " + when);
        }
    }
}
