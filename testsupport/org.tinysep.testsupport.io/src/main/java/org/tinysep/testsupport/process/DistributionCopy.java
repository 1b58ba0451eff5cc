package org.tinysep.testsupport.process;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.stream.Stream;

/**
 * Copies a built distribution ({@code runtime/org.tinysep.launcher/target/tinysep}) into a scratch home for one
 * test or benchmark, without its {@code var/} (each copy starts with no state). Written once for the launcher's
 * process tests, the integration tests' backup tests and the benchmarks.
 */
public final class DistributionCopy {

    private DistributionCopy() {
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
}
