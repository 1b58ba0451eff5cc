package org.tinysep.itests.lifecycle;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.DOOR;
import static org.tinysep.amica.protocol.AmicaNodeType.WINDOW;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.Bundle;
import org.osgi.framework.Version;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.TinySepTestSupport;
import org.tinysep.itests.Topology;

/**
 * Issue 6 point 1, the two other ways in: a jar dropped into, replaced in and deleted from a FileInstall-watched
 * deploy folder installs, updates and uninstalls the application; the plain Felix shell's {@code install},
 * {@code update} and {@code uninstall} do the same. Each time the device graph follows: the driver's devices appear,
 * keep their UIDs across the update, and vanish with the bundle.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class RuntimeChangesTest extends TinySepTestSupport {

    /** AmICA Door and Window are not provisioned: the tests bring them in. */
    @Override
    protected List<String> applications() {
        return List.of("org.tinysep.amica.protocol", "org.tinysep.amica.busradio.udp", "org.tinysep.flatoccupancy");
    }

    private static Path deployFolder() {
        return Path.of("target", "itest-deploy", RuntimeChangesTest.class.getSimpleName()).toAbsolutePath();
    }

    /** A second FileInstall watcher on the deploy folder, like the distribution's etc/ file. */
    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.apache.felix.fileinstall-deploy", Map.of("felix.fileinstall.dir", deployFolder().toString(),
                "felix.fileinstall.filter", ".*\\\\.jar", "felix.fileinstall.poll", "300",
                "felix.fileinstall.noInitialDelay", "true"));
        // the drivers list leaves hot-deployed bundles to FileInstall (no tinysep.home here to derive the folder from)
        configs.put("org.tinysep.drivers", Map.of("deployFolder", deployFolder().toString()));
        return configs;
    }

    @Test
    public void jarDroppedReplacedAndDeletedInTheDeployFolder() throws Exception {
        Path deploy = Files.createDirectories(deployFolder());
        try (Stream<Path> old = Files.list(deploy)) {
            for (Path f : old.toList()) {
                Files.delete(f);
            }
        }
        try (AmicaNode door = new AmicaNode(1, 20, udpPortOf(BUS), DOOR)) {
            door.keepAlive();
            expectTopology(Set.of(BUS + "@1.20"));

            Path jar = deploy.resolve("door.jar");
            atomicCopy(Files.readAllBytes(Path.of(java.net.URI.create(bundleUrl("org.tinysep.amica.door")))), jar);
            Set<String> withDoor = Set.of(BUS + "@1.20", "AmicaDoor@1.20",
                    "AmicaDoor@1.20 <- BusRadioAmicaProvider of " + BUS + "@1.20", "FlatOccupancy",
                    "FlatOccupancy <- DoorProvider of AmicaDoor@1.20");
            expectTopology(withDoor);
            String uid = Topology.uid(context, "AmicaDoor", "1.20");
            String devices = shell("tinysep:devices");
            assertTrue("the device manager lists the new device:\n" + devices, devices.contains(uid));
            String drivers = shell("tinysep:drivers");
            assertTrue("a hot-deployed bundle is FileInstall's, not the list's:\n" + drivers,
                    drivers.contains("org.tinysep.amica.door (not in the list)"));

            atomicCopy(NewBuild.withVersion(bundleUrl("org.tinysep.amica.door"), "0.1.200.deploy"), jar);
            await(TIMEOUT, () -> new Version(0, 1, 200, "deploy").equals(version("org.tinysep.amica.door")),
                    "the replaced jar to update the bundle");
            expectTopology(withDoor);
            assertEquals("same device after the update", uid, Topology.uid(context, "AmicaDoor", "1.20"));

            Files.delete(jar);
            await(TIMEOUT, () -> bundle("org.tinysep.amica.door") == null, "the deleted jar to uninstall the bundle");
            // Flat Occupancy stays without its door: it watches the person (issue 25, item 1)
            expectTopology(Set.of(BUS + "@1.20", "FlatOccupancy"));
            assertFalse(shell("tinysep:devices").contains(uid));
        }
    }

    @Test
    public void plainShellInstallUpdateUninstall() throws Exception {
        try (AmicaNode window = new AmicaNode(1, 30, udpPortOf(BUS), WINDOW)) {
            window.keepAlive();
            expectTopology(Set.of(BUS + "@1.30"));

            String out = shell("install " + bundleUrl("org.tinysep.amica.window"));
            Matcher id = Pattern.compile("Bundle ID: (\\d+)").matcher(out);
            assertTrue(out, id.find());
            shell("start " + id.group(1));
            Set<String> withWindow = Set.of(BUS + "@1.30", "AmicaWindow@1.30",
                    "AmicaWindow@1.30 <- BusRadioAmicaProvider of " + BUS + "@1.30");
            expectTopology(withWindow);
            String uid = Topology.uid(context, "AmicaWindow", "1.30");
            assertTrue(shell("tinysep:devices").contains(uid));
            await(TIMEOUT, () -> shell("tinysep:drivers").contains("org.tinysep.amica.window"),
                    "the shell install in the drivers list");

            Path build = Files.createTempFile(Path.of("target").toAbsolutePath(), "window-", ".jar");
            Files.write(build, NewBuild.withVersion(bundleUrl("org.tinysep.amica.window"), "0.1.300.shell"));
            shell("update " + id.group(1) + " " + build.toUri());
            assertEquals(new Version(0, 1, 300, "shell"), version("org.tinysep.amica.window"));
            expectTopology(withWindow);
            assertEquals("same device after the update", uid, Topology.uid(context, "AmicaWindow", "1.30"));

            shell("uninstall " + id.group(1));
            assertEquals(null, bundle("org.tinysep.amica.window"));
            expectTopology(Set.of(BUS + "@1.30"));
            assertFalse(shell("tinysep:devices").contains(uid));
            await(TIMEOUT, () -> !shell("tinysep:drivers").contains("org.tinysep.amica.window"),
                    "the shell uninstall to drop the entry");
            Files.delete(build);
        }
    }

    private static void atomicCopy(byte[] bytes, Path target) throws IOException {
        Path tmp = target.resolveSibling(target.getFileName() + ".part");
        Files.write(tmp, bytes);
        Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
    }

    private Bundle bundle(String bsn) {
        for (Bundle b : context.getBundles()) {
            if (bsn.equals(b.getSymbolicName())) {
                return b;
            }
        }
        return null;
    }

    private Version version(String bsn) {
        Bundle b = bundle(bsn);
        return b == null ? null : b.getVersion();
    }
}
