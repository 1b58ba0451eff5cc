package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Every topic of the contract (docs/mqtt.md, "Topic contract (v1)"), spelled out: the names must never drift. */
class TopicsTest {

    @Test
    void theContractsTopics() {
        Topics t = new Topics("care/tinysep", "flat-1", "homeassistant");
        assertEquals(List.of("care/tinysep/flat-1/status", "care/tinysep/flat-1/platform", "care/tinysep/flat-1/summary",
                "care/tinysep/flat-1/occupancy", "care/tinysep/flat-1/device/amica_1.17/state",
                "care/tinysep/flat-1/device/amica_1.17/availability", "care/tinysep/flat-1/device/amica_1.17/health",
                "care/tinysep/flat-1/alert/a_7", "care/tinysep/flat-1/alertkind/INACTIVITY",
                "care/tinysep/flat-1/command/device/amica_1.17", "care/tinysep/flat-1/command/device/+",
                "care/tinysep/flat-1/command/alert/+/ack", "care/tinysep/flat-1/command/",
                "care/tinysep/flat-1/command/result",
                "homeassistant/binary_sensor/tinysep_flat-1_amica_1.17/config", "tinysep_flat-1_occupancy"),
                List.of(t.status(), t.platform(), t.summary(), t.occupancy(), t.deviceState("amica/1.17"),
                        t.deviceAvailability("amica/1.17"), t.deviceHealth("amica/1.17"), t.alert("a#7"),
                        t.alertKind("INACTIVITY"), t.deviceCommand("amica/1.17"), t.deviceCommands(), t.alertAcks(),
                        t.commandPrefix(), t.commandResult(), t.discoveryConfig("binary_sensor", "amica/1.17"),
                        t.uniqueId("occupancy")));
    }
}
