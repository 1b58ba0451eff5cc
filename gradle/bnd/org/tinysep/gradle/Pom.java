package org.tinysep.gradle;

import java.io.File;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.parsers.DocumentBuilderFactory;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

/**
 * A module's pom.xml as the Gradle build reads it: the one source of dependencies and versions. Properties and
 * dependencyManagement are inherited from the parent poms (relativePath, by default the pom of the folder above); ${...} is resolved.
 */
public final class Pom {
    /** One dependency: coordinates with the version resolved, Maven scope, type and excluded groupId:artifactId. */
    public record Dep(String groupId, String artifactId, String version, String scope, String type,
            List<String> exclusions) {
        public String notation() {
            return groupId + ":" + artifactId + ":" + version;
        }
        public boolean testJar() {
            return "test-jar".equals(type);
        }
    }

    private static final Pattern PROPERTY = Pattern.compile("\\$\\{([^}]+)}");

    public final File file;
    public final String groupId;
    public final String artifactId;
    public final String version;
    public final String packaging;
    public final String name;
    public final String description;
    public final List<String> modules = new ArrayList<>();
    public final List<Dep> dependencies = new ArrayList<>();
    private final Map<String, String> properties = new LinkedHashMap<>();
    private final Map<String, Dep> managed = new LinkedHashMap<>();

    public Pom(File file) {
        this.file = file;
        Element root = parse(file);
        Element parentRef = child(root, "parent");
        Pom parent = null;
        if (parentRef != null) {
            String rel = text(parentRef, "relativePath", null);
            File parentFile = rel == null ? new File(file.getAbsoluteFile().getParentFile().getParentFile(), "pom.xml")
                    : new File(file.getParentFile(), rel);
            if (parentFile.isDirectory()) {
                parentFile = new File(parentFile, "pom.xml");
            }
            parent = new Pom(parentFile);
            properties.putAll(parent.properties);
            managed.putAll(parent.managed);
        }
        String g = text(root, "groupId", parent == null ? null : parent.groupId);
        String v = text(root, "version", parent == null ? null : parent.version);
        artifactId = text(root, "artifactId", null);
        properties.put("project.groupId", g);
        properties.put("project.version", v);
        properties.put("project.artifactId", artifactId);
        Element props = child(root, "properties");
        if (props != null) {
            for (Element p : children(props)) {
                properties.put(p.getTagName(), p.getTextContent().trim());
            }
        }
        groupId = resolve(g);
        version = resolve(v);
        packaging = text(root, "packaging", "jar");
        name = resolve(text(root, "name", artifactId));
        String d = text(root, "description", "");
        description = resolve(d.replaceAll("\\s+", " "));
        Element mods = child(root, "modules");
        if (mods != null) {
            for (Element m : children(mods)) {
                modules.add(m.getTextContent().trim());
            }
        }
        Element dm = child(root, "dependencyManagement");
        if (dm != null) {
            for (Dep dep : deps(child(dm, "dependencies"), false)) {
                if ("import".equals(dep.scope())) {
                    importBom(dep);
                } else {
                    managed.put(dep.groupId() + ":" + dep.artifactId(), dep);
                }
            }
        }
        // the parent's own dependencies are inherited (e.g. JUnit for every module)
        if (parent != null) {
            dependencies.addAll(parent.dependencies);
        }
        dependencies.addAll(deps(child(root, "dependencies"), true));
    }

    /**
     * An imported BOM. Only JUnit's is used here, and its rule is fixed: Jupiter and Vintage carry the BOM's version,
     * the Platform 1.x for 5.x (5.14.1 gives 1.14.1). Anything else is refused, so a new BOM cannot go unnoticed.
     */
    private void importBom(Dep bom) {
        if (!"org.junit:junit-bom".equals(bom.groupId() + ":" + bom.artifactId())) {
            throw new IllegalStateException(file + ": the Gradle build reads no BOM but JUnit's, found " + bom.notation());
        }
        String v = bom.version();
        String platform = v.startsWith("5.") ? "1." + v.substring(2) : v;
        properties.put("junit.jupiter.bom.version", v);
        properties.put("junit.platform.bom.version", platform);
    }

    private String bomVersion(String groupId) {
        if (groupId.equals("org.junit.platform")) {
            return properties.get("junit.platform.bom.version");
        }
        if (groupId.equals("org.junit.jupiter") || groupId.equals("org.junit.vintage")) {
            return properties.get("junit.jupiter.bom.version");
        }
        return null;
    }

    private List<Dep> deps(Element list, boolean applyManagement) {
        List<Dep> out = new ArrayList<>();
        if (list == null) {
            return out;
        }
        for (Element d : children(list)) {
            String g = resolve(text(d, "groupId", null));
            String a = resolve(text(d, "artifactId", null));
            String v = text(d, "version", null);
            String s = text(d, "scope", null);
            Dep m = applyManagement ? managed.get(g + ":" + a) : null;
            if (v == null && m != null) {
                v = m.version();
            }
            if (v == null && applyManagement) {
                v = bomVersion(g);
            }
            if (s == null) {
                s = m != null && m.scope() != null ? m.scope() : applyManagement ? "compile" : null;
            }
            if (v == null && applyManagement) {
                throw new IllegalStateException(file + ": no version for " + g + ":" + a);
            }
            List<String> ex = new ArrayList<>();
            Element exs = child(d, "exclusions");
            if (exs != null) {
                for (Element e : children(exs)) {
                    ex.add(text(e, "groupId", "*") + ":" + text(e, "artifactId", "*"));
                }
            }
            out.add(new Dep(g, a, v == null ? null : resolve(v), s, text(d, "type", "jar"), ex));
        }
        return out;
    }

    /**
     * groupId:artifactId:version of every managed dependency outside this project's group: Maven's
     * dependencyManagement also fixes the versions of transitive dependencies, so Gradle forces them.
     */
    public List<String> managedVersions() {
        List<String> out = new ArrayList<>();
        for (Dep d : managed.values()) {
            if (!d.groupId().equals(groupId) && d.version() != null) {
                out.add(d.groupId() + ":" + d.artifactId() + ":" + resolve(d.version()));
            }
        }
        return out;
    }

    public String property(String key) {
        return properties.get(key);
    }

    public String resolve(String s) {
        if (s == null) {
            return null;
        }
        for (int i = 0; i < 10 && s.contains("${"); i++) {
            Matcher m = PROPERTY.matcher(s);
            StringBuilder b = new StringBuilder();
            while (m.find()) {
                String value = properties.get(m.group(1));
                m.appendReplacement(b, Matcher.quoteReplacement(value == null ? m.group() : value));
            }
            m.appendTail(b);
            s = b.toString();
        }
        return s;
    }

    private static Element parse(File f) {
        try {
            DocumentBuilderFactory f2 = DocumentBuilderFactory.newInstance();
            Document doc = f2.newDocumentBuilder().parse(f);
            return doc.getDocumentElement();
        } catch (Exception e) {
            throw new IllegalStateException("cannot read " + f + ": " + e.getMessage(), e);
        }
    }

    private static List<Element> children(Element e) {
        List<Element> out = new ArrayList<>();
        for (Node n = e.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element el) {
                out.add(el);
            }
        }
        return out;
    }

    private static Element child(Element e, String tag) {
        for (Element c : children(e)) {
            if (c.getTagName().equals(tag)) {
                return c;
            }
        }
        return null;
    }

    private static String text(Element e, String tag, String dflt) {
        Element c = child(e, tag);
        return c == null ? dflt : c.getTextContent().trim();
    }
}
