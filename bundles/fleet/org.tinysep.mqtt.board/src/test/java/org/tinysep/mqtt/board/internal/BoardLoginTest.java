package org.tinysep.mqtt.board.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Clock;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.testsupport.mqtt.Mosquitto;

/**
 * Issue 25 item 2: the board on a real Mosquitto that lets anyone in. Without a login it does not connect and says
 * "Monitoring reduced: "; with {@code allowAnonymous=true} it connects and warns loudly; its password comes from
 * {@code passwordFile} (a missing file refuses, an open one warns).
 */
class BoardLoginTest {

    @TempDir
    Path var;
    final List<String> problems = new CopyOnWriteArrayList<>();

    @Test
    void withoutALoginTheBoardDoesNotConnectUnlessAnonymousIsAllowed() throws Exception {
        assumeTrue(Mosquitto.isInstalled(), "Debian's mosquitto is not installed (scripts/install-deps.sh)");
        try (Mosquitto broker = Mosquitto.startDefault()) {
            try (Central central = new Central(Configs.board(Map.of("brokerUrl", broker.url(), "clientId", "anon-board")),
                    Clock.systemUTC(), null, var, problems::add)) {
                assertEquals(1, problems.size(), problems.toString());
                assertTrue(problems.get(0).startsWith("Monitoring reduced: the care centre's board does not connect"),
                        problems.get(0));
                Thread.sleep(1500); // a connection attempt would have reached the broker by now
                assertTrue(central.json().contains("\"connected\":false"), central.json());
                assertTrue(central.json().contains("no broker login is configured"), central.json());
                assertFalse(broker.log().contains("anon-board"), broker.log());
            }
            problems.clear();
            try (Central central = new Central(Configs.board(Map.of("brokerUrl", broker.url(), "clientId", "anon-board",
                    "allowAnonymous", true)), Clock.systemUTC(), null, var, problems::add)) {
                Conditions.await("the board connected with the override", Duration.ofSeconds(30),
                        () -> central.json().contains("\"connected\":true"), central::json);
                assertTrue(problems.stream().anyMatch(p -> p.contains("WITHOUT a login (allowAnonymous=true): anyone")),
                        problems.toString());
            }
        }
    }

    @Test
    void thePasswordComesFromItsFile() throws Exception {
        Map<String, Object> c = Map.of("brokerUrl", "tcp://127.0.0.1:1", "username", "care");
        BoardLogin missing = BoardLogin.of(Configs.board(c), var, problems::add);
        assertTrue(missing.refusal().startsWith("Monitoring reduced: "), missing.refusal());
        assertTrue(missing.refusal().contains(var.resolve("secrets/mqtt-board.password").toString()), missing.refusal());

        Path file = Files.writeString(var.resolve("pw"), "s3cret\nignored\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        problems.clear();
        BoardLogin open = BoardLogin.of(Configs.board(Map.of("brokerUrl", "tcp://127.0.0.1:1", "username", "care",
                "passwordFile", file.toString())), var, problems::add);
        assertEquals(null, open.refusal());
        assertEquals("s3cret", new String(open.password()));
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).contains("can be read by other users") && problems.get(0).contains("chmod 600"),
                problems.get(0));
    }
}
