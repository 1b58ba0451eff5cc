package org.tinysep.tools.process;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.stream.Stream;

/**
 * A scratch home for one run of a built distribution ({@code runtime/org.tinysep.launcher/target/tinysep}): a full
 * copy without {@code var/} ({@link #copy}: each copy starts with no state), or a light home whose {@code bundles/}
 * links to the distribution's and whose {@code etc/} is its own ({@link #linked}).
 */
public final class DistributionCopy {

    /** The launcher's jar in a distribution's folder. */
    public static final String JAR = "tinysep.jar";

    private DistributionCopy() {
    }

    /**
     * @return {@code dist}, checked to be a built distribution
     * @throws IOException naming the folder when it holds no {@code tinysep.jar}
     */
    public static Path require(Path dist) throws IOException {
        if (!Files.isRegularFile(dist.resolve(JAR))) {
            throw new IOException("no distribution at " + dist.toAbsolutePath()
                    + " (no " + JAR + "; build the launcher first: mvn -B -o package)");
        }
        return dist;
    }

    /** Copies {@code dist} (without {@code var/}) to {@code home}, replacing files already there. */
    public static void copy(Path dist, Path home) throws IOException {
        try (Stream<Path> files = Files.walk(dist)) {
            for (Path f : files.filter(p -> !dist.relativize(p).startsWith("var")).toList()) {
                Path target = home.resolve(dist.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(f, target, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
    }

    /**
     * Makes {@code home} a light home of {@code dist}, as {@code scripts/demo-flat.sh} makes one: {@code bundles}
     * a link to the distribution's, {@code etc/} a copy of its {@code *.cfg} files, an empty {@code deploy/}. Run it
     * with {@link PlatformLaunch#jar(Path)} pointing at {@code dist}'s jar and {@code --home home}.
     */
    public static void linked(Path dist, Path home) throws IOException {
        Path etc = home.resolve("etc");
        Files.createDirectories(etc);
        Files.createDirectories(home.resolve("deploy"));
        if (!Files.exists(home.resolve("bundles"))) {
            Files.createSymbolicLink(home.resolve("bundles"), dist.resolve("bundles").toAbsolutePath());
        }
        try (DirectoryStream<Path> cfgs = Files.newDirectoryStream(dist.resolve("etc"), "*.cfg")) {
            for (Path f : cfgs) {
                Files.copy(f, etc.resolve(f.getFileName()), StandardCopyOption.REPLACE_EXISTING);
            }
        }
    }

    /** Writes {@code home/etc/<pid>.cfg} ({@code text}: {@code key=value} lines), replacing the file. */
    public static void cfg(Path home, String pid, String text) throws IOException {
        Files.createDirectories(home.resolve("etc"));
        Files.writeString(home.resolve("etc").resolve(pid + ".cfg"), text);
    }
}
