package org.tinysep.simulator.replay;

import java.nio.file.Path;
import org.tinysep.testsupport.repo.RepoFiles;

/** Locates the real Ordonez files: the repository's copy in data/ordonez (its PROVENANCE.md: source, licence). */
final class OrdonezData {

    static final Path DIR = RepoFiles.require("data", "ordonez");

    private OrdonezData() {
    }

    /** @throws IllegalStateException when the file is missing from the clone, naming it */
    static Path file(String name) {
        return RepoFiles.require("data", "ordonez", name);
    }
}
