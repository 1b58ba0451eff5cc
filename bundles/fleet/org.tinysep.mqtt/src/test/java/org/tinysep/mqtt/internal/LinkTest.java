package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.mqtt.Mosquitto;
import org.tinysep.testsupport.mqtt.MqttTestClient;

/** The Paho link against a real Mosquitto: connect, publish, commands in, trouble in words, reconnect. */
class LinkTest extends LinkTestSupport {

    private Link link(String url) throws Exception {
        Settings s = Settings.parse(Map.of("brokerUrl", url, "flatId", "f1"), var);
        Topics topics = new Topics(s.topicPrefix(), s.flatId(), s.discoveryPrefix());
        return new Link(s, topics, executor, events);
    }

    private String next() throws InterruptedException {
        return events.next();
    }

    @Test
    void publishesTakesCommandsAndReconnectsAfterTheBrokerCameBack() throws Exception {
        try (Mosquitto broker = Mosquitto.startDefault();
                MqttTestClient board = MqttTestClient.connect(broker.url(), "board").subscribe("tinysep/f1/#")) {
            Link link = link(broker.url());
            link.connect();
            assertEquals("connected", next());
            link.publish(Message.state("tinysep/f1/status", "online"));
            assertEquals("published tinysep/f1/status true", next());
            board.await("tinysep/f1/status", "online", Duration.ofSeconds(30));
            board.publish("tinysep/f1/command/alert/3/ack", "{\"by\":\"Anna\"}", false);
            assertEquals("command tinysep/f1/command/alert/3/ack {\"by\":\"Anna\"}", next());

            broker.stop();
            assertTrue(next().startsWith("lost: "));
            link.connect();
            String failed = next();
            assertTrue(failed.startsWith("failed: broker unreachable: connection refused"), failed);
            broker.start();
            link.connect();
            assertEquals("connected", next());
            assertTrue(link.isConnected());
            link.close(2000);
            assertFalse(link.isConnected());
        }
    }

    @Test
    void anOrderlyCloseSaysOfflineRetained() throws Exception {
        try (Mosquitto broker = Mosquitto.startDefault()) {
            Link link = link(broker.url());
            link.connect();
            assertEquals("connected", next());
            link.close(2000);
            try (MqttTestClient later = MqttTestClient.connect(broker.url(), "later").subscribe("tinysep/f1/status")) {
                assertTrue(later.await("tinysep/f1/status", "offline", Duration.ofSeconds(30)).retained());
            }
        }
    }
}
