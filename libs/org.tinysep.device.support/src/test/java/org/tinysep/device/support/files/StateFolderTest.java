package org.tinysep.device.support.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class StateFolderTest {

    @Test
    void configuredPathWins() {
        assertEquals(Optional.of(Path.of("/etc/x.xml")), StateFolder.resolve(" /etc/x.xml ", "/v", "/h", "x.xml"));
    }

    @Test
    void varComesBeforeHome() {
        assertEquals(Optional.of(Path.of("/srv/state/house.xml")), StateFolder.resolve("", "/srv/state", "/h", "house.xml"));
    }

    @Test
    void homeVarWhenVarIsUnset() {
        assertEquals(Optional.of(Path.of("/opt/t/var/house.xml")), StateFolder.resolve(null, " ", "/opt/t", "house.xml"));
    }

    @Test
    void emptyWithoutAnyProperty() {
        assertTrue(StateFolder.resolve(null, null, null, "house.xml").isEmpty());
    }
}
