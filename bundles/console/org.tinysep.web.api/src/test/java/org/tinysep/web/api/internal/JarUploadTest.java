package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;

class JarUploadTest {

    private static byte[] jar(String bsn, String version) throws IOException {
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        if (bsn != null) {
            m.getMainAttributes().putValue("Bundle-SymbolicName", bsn);
        }
        if (version != null) {
            m.getMainAttributes().putValue("Bundle-Version", version);
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (JarOutputStream jar = new JarOutputStream(out, m)) {
            jar.putNextEntry(new ZipEntry("x/Y.class"));
            jar.write(new byte[] {1, 2, 3});
        }
        return out.toByteArray();
    }

    @Test
    void readsTheSymbolicNameAndVersion() throws IOException {
        JarUpload u = JarUpload.of(jar("org.example.driver;singleton:=true", "1.2.3"));
        assertEquals("org.example.driver", u.symbolicName());
        assertEquals("1.2.3", u.version());
        assertEquals("0.0.0", JarUpload.of(jar("a.b", null)).version());
    }

    @Test
    void refusesWhatIsNotABundleWithAClearMessage() throws IOException {
        ApiException empty = assertThrows(ApiException.class, () -> JarUpload.of(new byte[0]));
        assertEquals(400, empty.status());
        assertTrue(empty.getMessage().contains("empty"), empty.getMessage());
        ApiException text = assertThrows(ApiException.class, () -> JarUpload.of("hello".getBytes(StandardCharsets.UTF_8)));
        assertTrue(text.getMessage().contains("not a jar file"), text.getMessage());
        ApiException plainJar = assertThrows(ApiException.class, () -> JarUpload.of(jar(null, "1.0")));
        assertTrue(plainJar.getMessage().contains("no Bundle-SymbolicName"), plainJar.getMessage());
        ApiException shell = assertThrows(ApiException.class, () -> JarUpload.of(jar("a$(reboot)", "1.0")));
        assertEquals(400, shell.status());
        ApiException odd = assertThrows(ApiException.class, () -> JarUpload.of(jar("a b|c", "1.0")));
        assertTrue(odd.getMessage().contains("not a bundle symbolic name"), odd.getMessage());
        ByteArrayOutputStream zip = new ByteArrayOutputStream();
        try (ZipOutputStream z = new ZipOutputStream(zip)) {
            z.putNextEntry(new ZipEntry("readme.txt"));
            z.write(1);
        }
        ApiException noManifest = assertThrows(ApiException.class, () -> JarUpload.of(zip.toByteArray()));
        assertTrue(noManifest.getMessage().contains("no META-INF/MANIFEST.MF"), noManifest.getMessage());
    }
}
