package org.tinysep.launcher;

import java.nio.file.Path;
import java.util.List;

/**
 * One folder {@code bundles/<level>-<name>/} of the distribution: its jars are installed at start level
 * {@code level}, in file-name order.
 *
 * @param startLevel the start level of every bundle in the group (the folder's number)
 * @param name       the folder's name without the number (e.g. {@code boot})
 * @param jars       the group's jar files, sorted by file name
 */
public record BundleGroup(int startLevel, String name, List<Path> jars) {

    public BundleGroup {
        jars = List.copyOf(jars);
    }

    /** @return the folder name, e.g. {@code 1-boot} */
    public String label() {
        return startLevel + "-" + name;
    }
}
