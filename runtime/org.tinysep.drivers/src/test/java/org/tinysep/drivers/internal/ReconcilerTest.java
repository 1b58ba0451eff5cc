package org.tinysep.drivers.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ReconcilerTest {

    @TempDir
    Path home;
    private final FakeBundles fw = new FakeBundles();
    private Reconciler reconciler;

    @BeforeEach
    void setUp() throws IOException {
        Files.createDirectories(home.resolve("apps"));
        for (String n : List.of("a", "b", "c", "broken")) {
            Files.writeString(home.resolve("apps/" + n + ".jar"), "not read by the fake");
        }
        reconciler = new Reconciler(fw, new Locations(home), 5);
    }

    private static DriverEntry entry(String name, boolean enabled) {
        return new DriverEntry("apps/" + name + ".jar", "", enabled, "");
    }

    @Test
    void installsAndStartsEveryEnabledEntryAtTheApplicationLevel() {
        Reconciler.Result r = reconciler.apply(List.of(entry("a", true), entry("b", false)));
        assertEquals(List.of("install " + home.resolve("apps/a.jar").toUri() + " @5", "start a"), fw.calls);
        assertEquals("a", r.entries().get(0).symbolicName(), "FULL_NAME filled in from the bundle");
        assertEquals(Status.ACTIVE, r.entries().get(0).status());
        assertEquals(Status.DISABLED, r.entries().get(1).status());
    }

    @Test
    void reloadTouchesOnlyWhatChanged() {
        List<DriverEntry> first = reconciler.apply(List.of(entry("a", true), entry("b", true))).entries();
        fw.calls.clear();
        List<DriverEntry> next = List.of(first.get(0), first.get(1).withEnabled(false), entry("c", true));
        Reconciler.Result r = reconciler.apply(next);
        assertEquals(List.of("stop b", "install " + home.resolve("apps/c.jar").toUri() + " @5", "start c"), fw.calls,
                "a keeps running untouched");
        assertEquals(List.of("stopped b (disabled)", "installed c", "started c"), r.changes());
    }

    @Test
    void removedEntryIsUninstalledButForeignBundlesStay() {
        long foreign = fw.preinstalled("file:/elsewhere/x.jar", "x", true);
        List<DriverEntry> first = reconciler.apply(List.of(entry("a", true), entry("b", true))).entries();
        fw.calls.clear();
        Reconciler.Result r = reconciler.apply(List.of(first.get(1)));
        assertEquals(List.of("uninstall a"), fw.calls);
        assertEquals(List.of("uninstalled a (entry removed)"), r.changes());
        assertTrue(fw.isRunning(foreign), "a bundle the list never managed is never uninstalled");
        assertTrue(reconciler.uninstalled(-5).isEmpty());
    }

    @Test
    void enabledEntryThatWasStoppedIsStartedAgain() {
        List<DriverEntry> first = reconciler.apply(List.of(entry("a", true))).entries();
        fw.stop(fw.find("a", ""));
        fw.calls.clear();
        reconciler.apply(first);
        assertEquals(List.of("start a"), fw.calls);
    }

    @Test
    void adoptsAnAlreadyInstalledBundleOfTheSameName() {
        fw.preinstalled("file:/pax/a.jar", "a", true);
        reconciler.apply(List.of(new DriverEntry("apps/a.jar", "a", true, "")));
        assertTrue(fw.calls.isEmpty(), "running and adopted: " + fw.calls);
    }

    @Test
    void missingFileAndInstallFailureBecomeStatuses() {
        Reconciler.Result r = reconciler.apply(List.of(entry("gone", true), entry("broken", true), entry("a", true)));
        assertTrue(r.entries().get(0).status().startsWith("MISSING: "), r.entries().get(0).status());
        assertEquals("FAILED: invalid manifest", r.entries().get(1).status());
        assertEquals(Status.ACTIVE, r.entries().get(2).status(), "one bad entry never stops the others");
    }

    /** Issue 10 item 4: a drivers-list URL is installed only when it is file: or https:. */
    @Test
    void anHttpOrOtherUrlIsNotInstalled() {
        Reconciler.Result r = reconciler.apply(List.of(new DriverEntry("http://example.org/evil.jar", "", true, ""),
                new DriverEntry("mvn:org.x/y/1.0", "", true, ""), entry("a", true)));
        assertEquals("FAILED: http: URLs are not installed, only file: and https: (docs/runtime-changes.md)",
                r.entries().get(0).status());
        assertTrue(r.entries().get(1).status().startsWith("FAILED: mvn: URLs are not installed"));
        assertTrue(fw.calls.stream().noneMatch(c -> c.contains("example.org") || c.contains("mvn:")), fw.calls.toString());
        assertEquals(Status.ACTIVE, r.entries().get(2).status());
        Locations l = new Locations(home);
        assertTrue(l.refusal("https://example.org/a.jar").isEmpty());
        assertTrue(l.refusal("file:/srv/a.jar").isEmpty());
        assertTrue(l.refusal("apps/a.jar").isEmpty());
    }

    @Test
    void aShellUninstallIsReportedOnceAndOwnUninstallsNot() {
        List<DriverEntry> first = reconciler.apply(List.of(entry("a", true), entry("b", true))).entries();
        long a = fw.find("a", "");
        long b = fw.find("b", "");
        reconciler.apply(List.of(first.get(1))); // the list uninstalls a
        assertTrue(reconciler.uninstalled(a).isEmpty(), "own uninstall");
        assertEquals("b", reconciler.uninstalled(b).orElseThrow(), "someone else uninstalled b");
        assertTrue(!reconciler.manages(b));
    }
}
