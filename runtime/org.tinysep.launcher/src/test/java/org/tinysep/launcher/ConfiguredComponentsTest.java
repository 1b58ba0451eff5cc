package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.launcher.ConfiguredComponents.Component;
import org.tinysep.launcher.ConfiguredComponents.Configuration;

/**
 * Issue 29 (start): "ready" waits until every Declarative Services component configured by a file of {@code etc/}
 * runs with that file's configuration — checked, instead of a fixed 300 ms of a quiet service registry.
 */
class ConfiguredComponentsTest {

    private static final String UDP = "org.tinysep.amica.busradio.udp.cfg";
    private static final Set<String> FILES = Set.of(UDP, "org.apache.felix.fileinstall-deploy.cfg",
            "org.apache.felix.http.cfg");

    @Test
    void aRadioActiveWithItsFileIsReady() {
        assertEquals(Set.of(), ConfiguredComponents.waitingFor(FILES, List.of(radio(ConfiguredComponents.ACTIVE, UDP))));
    }

    @Test
    void aRadioActiveWithoutItsFileYetIsWaitedFor() {
        // it activated with its defaults before FileInstall handed ConfigAdmin the file: a reactivation follows
        assertEquals(Set.of(UDP), ConfiguredComponents.waitingFor(FILES, List.of(radio(ConfiguredComponents.ACTIVE, null))));
    }

    @Test
    void anImmediateRadioOnlySatisfiedIsStillActivating() {
        assertEquals(Set.of(UDP), ConfiguredComponents.waitingFor(FILES, List.of(radio(ConfiguredComponents.SATISFIED, UDP))));
    }

    @Test
    void aDelayedComponentSatisfiedWithItsFileIsReady() {
        Component delayed = new Component(List.of("org.tinysep.amica.busradio.udp"), false,
                List.of(new Configuration(ConfiguredComponents.SATISFIED, "file:/home/etc/" + UDP)));
        assertEquals(Set.of(), ConfiguredComponents.waitingFor(FILES, List.of(delayed)));
    }

    @Test
    void aComponentWaitingForAServiceHasItsFileAlready() {
        assertEquals(Set.of(), ConfiguredComponents.waitingFor(FILES,
                List.of(radio(ConfiguredComponents.UNSATISFIED_REFERENCE, UDP))));
    }

    @Test
    void filesNoComponentIsConfiguredByAreNotWaitedFor() {
        // Felix HTTP and FileInstall's deploy/ watcher take theirs as ManagedService(Factory), not through DS
        assertEquals(Set.of(), ConfiguredComponents.waitingFor(FILES, List.of()));
    }

    @Test
    void aFactoryConfigurationFileIsMatchedByItsFactoryPid() {
        String file = "org.tinysep.mqtt.bridge-home.cfg";
        Component bridge = new Component(List.of("org.tinysep.mqtt.bridge"), true, List.of());
        assertEquals(Set.of(file), ConfiguredComponents.waitingFor(Set.of(file), List.of(bridge)));
        Component running = new Component(List.of("org.tinysep.mqtt.bridge"), true,
                List.of(new Configuration(ConfiguredComponents.ACTIVE, "file:/home/etc/" + file)));
        assertEquals(Set.of(), ConfiguredComponents.waitingFor(Set.of(file), List.of(running)));
    }

    private static Component radio(int state, String file) {
        return new Component(List.of("org.tinysep.amica.busradio.udp"), true,
                List.of(new Configuration(state, file == null ? "" : "file:/home/etc/" + file)));
    }
}
