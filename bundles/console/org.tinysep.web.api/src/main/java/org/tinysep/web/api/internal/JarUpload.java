package org.tinysep.web.api.internal;

import jakarta.servlet.http.HttpServletRequest;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.Locale;
import java.util.Set;
import java.util.jar.JarInputStream;
import java.util.jar.Manifest;

/**
 * A bundle jar sent as the raw request body ({@code Content-Type: application/java-archive}, also
 * {@code application/octet-stream} or {@code application/zip}), at most {@value #MAX_BYTES} bytes, checked before
 * anything is written: a jar with a manifest naming {@code Bundle-SymbolicName} (parameters such as
 * {@code ;singleton:=true} cut off) that matches {@link DriversListAccess#BSN}.
 *
 * @param bytes        the jar
 * @param symbolicName its Bundle-SymbolicName
 * @param version      its Bundle-Version (0.0.0 when absent)
 */
record JarUpload(byte[] bytes, String symbolicName, String version) {

    static final int MAX_BYTES = 32 * 1024 * 1024;
    private static final Set<String> TYPES = Set.of("application/java-archive", "application/octet-stream",
            "application/zip", "application/x-java-archive");

    static JarUpload read(HttpServletRequest req) throws IOException {
        String type = req.getContentType() == null ? "" : req.getContentType().toLowerCase(Locale.ROOT);
        int semi = type.indexOf(';');
        if (!TYPES.contains((semi < 0 ? type : type.substring(0, semi)).strip())) {
            throw new ApiException(415, "send the bundle jar itself as the request body "
                    + "(Content-Type: application/java-archive)");
        }
        byte[] bytes;
        try (InputStream in = req.getInputStream()) {
            bytes = in.readNBytes(MAX_BYTES + 1);
        }
        if (bytes.length > MAX_BYTES) {
            throw new ApiException(413, "the jar is larger than " + MAX_BYTES / (1024 * 1024) + " MiB");
        }
        return of(bytes);
    }

    static JarUpload of(byte[] bytes) {
        if (bytes.length == 0) {
            throw ApiException.badRequest("the upload is empty: choose a bundle jar");
        }
        if (bytes.length < 4 || bytes[0] != 'P' || bytes[1] != 'K' || bytes[2] != 3 || bytes[3] != 4) {
            throw ApiException.badRequest("the upload is not a jar file (a bundle jar is a zip archive): choose the driver's .jar");
        }
        Manifest manifest;
        try (JarInputStream jar = new JarInputStream(new ByteArrayInputStream(bytes))) {
            manifest = jar.getManifest();
        } catch (IOException | RuntimeException e) {
            throw ApiException.badRequest("the upload is not a jar file: " + e.getMessage());
        }
        if (manifest == null) {
            throw ApiException.badRequest("the upload is not a bundle: its jar has no META-INF/MANIFEST.MF");
        }
        String bsn = manifest.getMainAttributes().getValue("Bundle-SymbolicName");
        if (bsn == null || bsn.isBlank()) {
            throw ApiException.badRequest("the upload is not an OSGi bundle: its manifest has no Bundle-SymbolicName");
        }
        bsn = bsn.split(";", 2)[0].strip();
        DriversListAccess.checked(bsn);
        String version = manifest.getMainAttributes().getValue("Bundle-Version");
        return new JarUpload(bytes, bsn, version == null || version.isBlank() ? "0.0.0" : version.strip());
    }
}
