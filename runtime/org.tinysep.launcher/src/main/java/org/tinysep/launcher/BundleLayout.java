package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Reads the distribution's {@code bundles/} folder: every sub-folder named {@code <level>-<name>}
 * (e.g. {@code 1-boot}, {@code 5-apps}) is a {@link BundleGroup} started at that level. Other folders and
 * files are ignored with a warning. Groups are ordered by level, then by name.
 */
public final class BundleLayout {

    private static final Logger LOG = LoggerFactory.getLogger(BundleLayout.class);
    private static final Pattern GROUP = Pattern.compile("(\\d{1,3})-(.+)");

    private BundleLayout() {
    }

    /**
     * Scans {@code bundlesDir}.
     *
     * @return the groups in start order; empty groups are kept (they still raise the start level)
     * @throws IOException when {@code bundlesDir} cannot be listed
     */
    public static List<BundleGroup> scan(Path bundlesDir) throws IOException {
        List<BundleGroup> groups = new ArrayList<>();
        try (Stream<Path> children = Files.list(bundlesDir)) {
            for (Path child : children.sorted().toList()) {
                Matcher m = GROUP.matcher(child.getFileName().toString());
                if (!Files.isDirectory(child) || !m.matches() || Integer.parseInt(m.group(1)) < 1) {
                    LOG.warn("Ignoring {}: expected a folder named <start level ≥ 1>-<name>, e.g. 5-apps", child);
                    continue;
                }
                groups.add(new BundleGroup(Integer.parseInt(m.group(1)), m.group(2), jarsIn(child)));
            }
        }
        groups.sort(Comparator.comparingInt(BundleGroup::startLevel).thenComparing(BundleGroup::name));
        return groups;
    }

    /** @return the highest start level of {@code groups}, at least 1 */
    public static int maxStartLevel(List<BundleGroup> groups) {
        return groups.stream().mapToInt(BundleGroup::startLevel).max().orElse(1);
    }

    private static List<Path> jarsIn(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(f -> Files.isRegularFile(f) && f.getFileName().toString().endsWith(".jar"))
                    .sorted(Comparator.comparing(f -> f.getFileName().toString()))
                    .toList();
        }
    }
}
