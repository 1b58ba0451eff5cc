package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.http.HttpResponse;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;

/** Guessing passwords is slowed down: after 5 failures within a minute, even the right password is refused (429). */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebLoginLimitTest extends WebTestSupport {

    @Test
    public void loginsAreRateLimited() {
        HttpResponse<String> before = call("POST", "/api/session", "{\"user\":\"installer\",\"password\":\"whatever-1\"}", null, false);
        assertEquals(before.body(), 403, before.statusCode());
        assertTrue("no password yet says how to set one: " + before.body(), before.body().contains("tinysep:web-password"));
        setPasswords();
        for (int i = 0; i < 5; i++) {
            assertEquals(401, call("POST", "/api/session", "{\"user\":\"installer\",\"password\":\"guess-" + i + "\"}", null, false).statusCode());
        }
        HttpResponse<String> limited = call("POST", "/api/session",
                "{\"user\":\"installer\",\"password\":\"" + INSTALLER_PASSWORD + "\"}", null, false);
        assertEquals(limited.body(), 429, limited.statusCode());
        assertTrue(limited.body(), limited.body().contains("too many failed logins"));
        assertTrue(limited.headers().firstValue("Retry-After").isPresent());
    }
}
