package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Test;

/** Issue 25, item 3: an upload does not replace an application that watches the person without an explicit flag. */
class UploadRefusalTest {

    @Test
    void replacingAWatchingApplicationByUploadNeedsTheFlag() {
        String why = ApplicationInstaller.refusal("org.tinysep.inactivity", true, false).orElseThrow();
        assertTrue(why.contains("watches the person") && why.contains("replaceWatching=true"), why);
        assertEquals(Optional.empty(), ApplicationInstaller.refusal("org.tinysep.inactivity", true, true));
        assertEquals(Optional.empty(), ApplicationInstaller.refusal("org.tinysep.inactivity", false, false));
        assertEquals(Optional.empty(), ApplicationInstaller.refusal("org.tinysep.amica.window", true, false));
    }
}
