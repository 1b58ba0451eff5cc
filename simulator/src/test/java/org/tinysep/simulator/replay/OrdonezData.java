package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;

/** Locates the real Ordonez files: ../../shared/data/ordonez relative to the module (Maven's working directory). */
final class OrdonezData {

    static final Path DIR = Path.of("../../shared/data/ordonez");

    private OrdonezData() {
    }

    static Path file(String name) {
        Path p = DIR.resolve(name);
        if (!Files.isReadable(p)) {
            fail("Ordonez data file " + p.toAbsolutePath().normalize() + " is missing; the replay tests need the "
                    + "UCI data set 271 files in /work/shared/data/ordonez (run Maven from the simulator module or "
                    + "the reactor root, so the module is the working directory)");
        }
        return p;
    }
}
