package org.tinysep.amica.window.tutorial;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.platform.launcher.listeners.TestExecutionSummary;
import org.tinysep.testsupport.repo.RepoFiles;

/**
 * Keeps {@code docs/tutorial-new-sensor.md} honest by following it in a scratch folder (see {@link Workspace}):
 * the copy script must run, every diff must still apply to the current files, every Java file must compile
 * against this module's test class path (the APIs the tutorial uses must exist as written), and the example's
 * unit test and the patched protocol test must pass. Paths and anchors it names must exist.
 */
class TutorialNewSensorTest {

    static final String TUTORIAL = "docs/tutorial-new-sensor.md";
    static final String NEW_MODULE = "bundles/sensors/org.tinysep.amica.waterleak";
    private static final Pattern NEW_NAME = Pattern.compile("waterleak|WaterLeak|water-leak|WATER_LEAK");

    @TempDir
    static Path scratch;
    private static Workspace tutorial;
    private static Path classes;

    @BeforeAll
    static void followTheTutorial() throws Exception {
        RepoFiles.require(TUTORIAL);
        tutorial = Workspace.follow(RepoFiles.root(), scratch.resolve("repo"), TUTORIAL);
    }

    @Test
    void everyRepositoryPathItNamesExists() throws IOException {
        Set<String> top = new TreeSet<>();
        try (Stream<Path> entries = Files.list(tutorial.repo)) {
            entries.forEach(p -> top.add(p.getFileName().toString()));
        }
        List<String> missing = new ArrayList<>();
        int checked = 0;
        for (String span : tutorial.page.codeSpans()) {
            if (!span.contains("/") || span.matches(".*[\\s<>*].*") || !top.contains(span.split("/")[0])) {
                continue; // not a repository path
            }
            checked++;
            boolean isNew = NEW_NAME.matcher(span).find();
            Path where = (isNew ? tutorial.root : tutorial.repo).resolve(span);
            if (!Files.exists(where)) {
                missing.add(span + (isNew ? " (not made by the tutorial's steps)" : ""));
            }
        }
        for (String link : tutorial.page.links()) {
            if (link.startsWith("#") || link.contains("://")) {
                continue;
            }
            checked++;
            if (!Files.exists(tutorial.repo.resolve("docs").resolve(link).normalize())) {
                missing.add(link);
            }
        }
        for (String file : tutorial.files) {
            if (!NEW_NAME.matcher(file).find()) {
                missing.add(file + " (a complete file for a path that already exists: use a diff)");
            }
        }
        assertTrue(checked >= 10, "only " + checked + " paths found: is the tutorial still there?");
        assertEquals(List.of(), missing, "paths named by " + TUTORIAL);
    }

    @Test
    void everyAnchorItLinksToExists() {
        for (String link : tutorial.page.links()) {
            if (link.startsWith("#")) {
                assertTrue(tutorial.page.anchors().contains(link.substring(1)), "no heading for " + link);
            }
        }
    }

    @Test
    void itsJavaCompilesAndTheExampleAndPatchedProtocolTestsPass() throws Exception {
        Path out = compiled();
        List<Class<?>> tests = new ArrayList<>();
        try (URLClassLoader loader = JavaBuild.childFirst(out, getClass().getClassLoader());
                Stream<Path> all = Files.walk(out)) {
            for (Path f : all.filter(p -> p.getFileName().toString().matches("[A-Za-z0-9]+Test\\.class")).toList()) {
                String name = out.relativize(f).toString().replace('/', '.').replace('\\', '.');
                tests.add(loader.loadClass(name.substring(0, name.length() - ".class".length())));
            }
            assertEquals(Set.of("AmicaNodeTypeTest", "AmicaWaterLeakDeviceTest"),
                    Set.copyOf(tests.stream().map(Class::getSimpleName).toList()), "test classes the tutorial makes");
            TestExecutionSummary summary = JavaBuild.runTests(tests, loader);
            StringBuilder failures = new StringBuilder();
            summary.getFailures().forEach(f -> failures.append(f.getTestIdentifier().getDisplayName()).append(": ")
                    .append(f.getException()).append('\n'));
            assertEquals("", failures.toString(), "tests of the tutorial's code");
            assertTrue(summary.getTestsSucceededCount() >= 6, summary.getTestsSucceededCount() + " tests ran");
        }
    }

    @Test
    void theNewModuleKeepsNoTraceOfItsSibling() throws IOException {
        Path module = tutorial.file(NEW_MODULE);
        Set<String> expected = Set.of("pom.xml", "bnd.bnd", "README.md", "AmicaWaterLeakDriver.java",
                "AmicaWaterLeakDevice.java", "AmicaWaterLeakDeviceTest.java", "FakeBus.java");
        Set<String> found = new TreeSet<>();
        List<String> traces = new ArrayList<>();
        try (Stream<Path> all = Files.walk(module)) {
            for (Path f : all.filter(Files::isRegularFile).toList()) {
                found.add(f.getFileName().toString());
                if (Pattern.compile("window", Pattern.CASE_INSENSITIVE).matcher(Files.readString(f)).find()
                        || f.toString().toLowerCase().contains("window")) {
                    traces.add(module.relativize(f).toString());
                }
            }
        }
        assertEquals(new TreeSet<>(expected), found, "files of " + NEW_MODULE);
        assertEquals(List.of(), traces, "files that still mention the window");
        assertEquals("-conditionalpackage: org.tinysep.device.support.*\n"
                + "-dsannotations-options: inherit", Files.readString(module.resolve("bnd.bnd")).strip());
    }

    @Test
    void theModuleIsRegisteredEverywhereAndEveryPatchedPomIsWellFormed() throws Exception {
        String artifact = NEW_MODULE.substring(NEW_MODULE.lastIndexOf('/') + 1);
        assertEquals(artifact, Poms.text(tutorial.file(NEW_MODULE + "/pom.xml"), "/project/artifactId"));
        assertTrue(Poms.texts(tutorial.file("bundles/pom.xml"), "/project/modules/module")
                .contains(NEW_MODULE.substring("bundles/".length())));
        assertTrue(Poms.texts(tutorial.file("runtime/org.tinysep.launcher/pom.xml"),
                "/project/dependencies/dependency/artifactId").contains(artifact));
        Path itests = tutorial.file("itests/pom.xml");
        assertTrue(Poms.texts(itests, "/project/dependencies/dependency/artifactId").contains(artifact));
        assertEquals("${org.tinysep:" + artifact + ":jar}", Poms.text(itests,
                "//plugin[artifactId='maven-surefire-plugin']/configuration/systemPropertyVariables/bundle." + artifact));
        String support = Files.readString(tutorial.file("itests/src/test/java/org/tinysep/itests/TinySepTestSupport.java"));
        assertTrue(support.matches("(?s).*AMICA_HARDWARE = List\\.of\\([^;]*\"" + Pattern.quote(artifact) + "\"\\);.*"),
                "TinySepTestSupport.AMICA_HARDWARE lists " + artifact);
        for (String path : tutorial.patched) {
            if (path.endsWith(".xml")) {
                Poms.text(tutorial.file(path), "/project/modelVersion"); // parses it
            }
        }
    }

    @Test
    void theIntegrationTestUsesOnlyThingsThatExist() throws Exception {
        List<String> itests = tutorial.files.stream().filter(f -> f.startsWith("itests/")).toList();
        assertEquals(1, itests.size(), "one integration test in the tutorial");
        Path source = tutorial.file(itests.get(0));
        try (URLClassLoader loader = JavaBuild.childFirst(compiled(), getClass().getClassLoader())) {
            List<String> problems = Imports.check(Files.readString(source), loader, tutorial.repo, tutorial.root);
            assertEquals(List.of(), problems, itests.get(0));
        }
    }

    /** Compiles every Java file the tutorial made or patched, except the sibling copy and the Pax Exam test. */
    private static synchronized Path compiled() throws IOException {
        if (classes != null) {
            return classes;
        }
        List<Path> sources;
        try (Stream<Path> all = Files.walk(tutorial.root)) {
            sources = all.filter(p -> p.toString().endsWith(".java"))
                    .filter(p -> !p.startsWith(tutorial.file(Workspace.SIBLING)) && !p.startsWith(tutorial.file("itests")))
                    .toList();
        }
        Path out = scratch.resolve("classes");
        String errors = JavaBuild.compile(sources, out);
        if (!errors.isEmpty()) {
            fail("the tutorial's Java does not compile against the current code:\n" + errors);
        }
        classes = out;
        return out;
    }
}
