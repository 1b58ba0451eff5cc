package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Which cfg files an archive may carry, and the keys it never carries or changes (docs/backup.md). */
class OwnedConfigTest {

    @Test
    void onlyTheShippedBundlesPidsAreOwned() {
        assertTrue(OwnedConfig.owned("org.tinysep.timecontroller.cfg"));
        assertTrue(OwnedConfig.owned("org.tinysep.amica.busradio.serial-usb0.cfg"), "factory configuration");
        assertFalse(OwnedConfig.owned("org.tinysep.amica.busradio.serial.cfg"), "a factory PID is no singleton");
        assertFalse(OwnedConfig.owned("org.tinysep.timecontroller-x.cfg"), "a singleton PID is no factory");
        assertFalse(OwnedConfig.owned("org.apache.felix.fileinstall-deploy.cfg"));
        assertFalse(OwnedConfig.owned("org.tinysep.evil.cfg"), "an org.tinysep name alone is not enough");
        assertFalse(OwnedConfig.owned("org.tinysep.mailmanager.config"));
    }

    @Test
    void passwordsAreLeftOutOfBackupsWhateverTheirSpelling() {
        String cfg = "# mail\nhost=127.0.0.1\npassword = very\\\n    long\\\\\nPassword:x\nuser=anna\\\n  b\n"
                + "syncSecret=abc\npasswordFile=/x\n";
        assertEquals("# mail\nhost=127.0.0.1\nuser=anna\\\n  b\n", text(OwnedConfig.forBackup(bytes(cfg))));
    }

    @Test
    void aRestoreKeepsTheModePasswordAndPlacesOfThisInstallationInTheirPlace() {
        OwnedConfig.Merged m = OwnedConfig.forRestore("org.tinysep.timecontroller.cfg",
                bytes("mode=EXTERNAL\nsyncPort=1\n"), bytes("syncPort=2\nmode=REAL\n"));
        assertEquals("mode=REAL\nsyncPort=1\n", text(m.content()));
        assertEquals(1, m.notes().size());
        m = OwnedConfig.forRestore("org.tinysep.drivers.cfg", bytes("file=/tmp/evil/drivers.xml\nstartLevel=5\n"), null);
        assertEquals("startLevel=5\n", text(m.content()));
        assertEquals(List.of("org.tinysep.drivers.cfg: kept this installation's file (not set); the archive's "
                + "/tmp/evil/drivers.xml was not applied"), m.notes());
        m = OwnedConfig.forRestore("org.tinysep.mailmanager.cfg", bytes("host=a\n"), bytes("host=b\npassword=p\n"));
        assertEquals("host=a\npassword=p\n", text(m.content()));
        assertTrue(m.notes().isEmpty(), "the archive wanted nothing different: " + m.notes());
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private static String text(byte[] b) {
        return new String(b, StandardCharsets.UTF_8);
    }
}
