package org.tinysep.gradle;

import aQute.bnd.header.Attrs;
import aQute.bnd.header.Parameters;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.jar.JarFile;
import java.util.jar.Manifest;
import java.util.zip.ZipEntry;

/**
 * Compares a Gradle-built bundle with the Maven-built one: the OSGi headers (parsed, so the order of clauses and
 * attributes does not count; Bundle-Version without its build-time qualifier), the DS component descriptions under
 * OSGI-INF/ and the list of class files (what -conditionalpackage and -includeresource put in).
 */
public final class ManifestCompare {
    static final List<String> HEADERS = List.of("Bundle-SymbolicName", "Bundle-Version", "Bundle-Name",
            "Export-Package", "Import-Package", "DynamicImport-Package", "Provide-Capability", "Require-Capability",
            "Service-Component", "Main-Class", "Class-Path");

    private ManifestCompare() {
    }

    /** The differences, one line each, naming the header or entry; empty when the bundles agree. */
    public static List<String> differences(File maven, File gradle) throws Exception {
        List<String> out = new ArrayList<>();
        try (JarFile m = new JarFile(maven); JarFile g = new JarFile(gradle)) {
            Manifest mm = m.getManifest();
            Manifest gm = g.getManifest();
            for (String h : HEADERS) {
                String a = normal(h, mm.getMainAttributes().getValue(h));
                String b = normal(h, gm.getMainAttributes().getValue(h));
                if (!a.equals(b)) {
                    out.add(h + ": Maven has [" + a + "], Gradle has [" + b + "]");
                }
            }
            TreeMap<String, String> ma = entries(m);
            TreeMap<String, String> ga = entries(g);
            for (String e : new TreeSet<>(ma.keySet())) {
                if (!ga.containsKey(e)) {
                    out.add("entry " + e + " only in Maven's bundle");
                } else if (!ma.get(e).equals(ga.get(e))) {
                    out.add("entry " + e + " differs");
                }
            }
            for (String e : ga.keySet()) {
                if (!ma.containsKey(e)) {
                    out.add("entry " + e + " only in Gradle's bundle");
                }
            }
        }
        return out;
    }

    /** Class files (by name) and OSGI-INF/ descriptions (by content). */
    private static TreeMap<String, String> entries(JarFile j) throws Exception {
        TreeMap<String, String> out = new TreeMap<>();
        for (ZipEntry e : java.util.Collections.list(j.entries())) {
            if (e.getName().endsWith(".class")) {
                out.put(e.getName(), "");
            } else if (e.getName().startsWith("OSGI-INF/") && !e.isDirectory()) {
                try (InputStream in = j.getInputStream(e)) {
                    ByteArrayOutputStream b = new ByteArrayOutputStream();
                    in.transferTo(b);
                    out.put(e.getName(), b.toString(java.nio.charset.StandardCharsets.UTF_8));
                }
            }
        }
        return out;
    }

    static String normal(String header, String value) {
        if (value == null) {
            return "";
        }
        if (header.equals("Bundle-Version")) {
            String[] p = value.split("\\.");
            return String.join(".", Arrays.copyOf(p, Math.min(3, p.length)));
        }
        if (header.equals("Bundle-Name") || header.equals("Main-Class") || header.equals("Class-Path")) {
            return value.trim();
        }
        Parameters ps = new Parameters(value, null, true);
        StringBuilder b = new StringBuilder();
        for (Map.Entry<String, Attrs> c : toMap(ps).entrySet()) {
            b.append(c.getKey());
            for (String k : new TreeSet<>(c.getValue().keySet())) {
                String v = c.getValue().get(k);
                if (k.startsWith("uses")) {
                    v = String.join(",", new TreeSet<>(Arrays.asList(v.split("\\s*,\\s*"))));
                }
                b.append(';').append(k).append('=').append(v);
            }
            b.append(", ");
        }
        return b.toString();
    }

    private static Map<String, Attrs> toMap(Parameters ps) {
        TreeMap<String, Attrs> m = new TreeMap<>();
        for (Map.Entry<String, Attrs> e : ps.entrySet()) {
            m.put(e.getKey(), e.getValue());
        }
        return m;
    }
}
