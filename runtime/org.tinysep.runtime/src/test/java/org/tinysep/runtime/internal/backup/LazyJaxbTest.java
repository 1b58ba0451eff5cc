package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;

/**
 * JAXB's context is made only for a file the reader without JAXB declines: a codec that writes and reads its own
 * files (every save, every restore of an ordinary start) makes none, so none of JAXB's classes load (issue 29).
 */
class LazyJaxbTest {

    @Test
    void writingAndReadingItsOwnFilesMakesNoJaxbContext() throws Exception {
        BackupCodec codec = new BackupCodec();
        for (int i = 0; i < 200; i++) {
            ComponentBackup b = backup("movement-1.17." + i);
            assertEquals(b, codec.read(codec.write(b)));
        }
        assertFalse(codec.jaxbMade(), "JAXB context made while reading the codec's own files");
    }

    @Test
    void aFileOfAnotherShapeIsStillReadByJaxb() throws Exception {
        BackupCodec codec = new BackupCodec();
        ComponentBackup b = backup("door-1.20");
        String own = new String(codec.write(b), StandardCharsets.UTF_8);
        byte[] edited = own.replace("<backup ", "<!-- edited by hand -->\n<backup ").getBytes(StandardCharsets.UTF_8);
        assertEquals(b, codec.read(edited));
        assertTrue(codec.jaxbMade(), "the edited file was read by JAXB");
    }

    private static ComponentBackup backup(String uid) {
        return new ComponentBackup(uid, ComponentKind.DEVICE, "amica-movement", "AmICA Movement", "movement",
                "Movement " + uid, Map.of("room", "kitchen"), "1.17", List.of("movement"),
                Instant.parse("2026-11-29T10:00:00Z"), Map.of("motion", "false"), Instant.parse("2026-11-29T10:00:05Z"));
    }
}
