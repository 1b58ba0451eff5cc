package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.repo.RepoFiles;

/** ./evaluate.sh reads the repository's copy of the Ordonez data unless told otherwise (issue 32). */
class EvalOptionsTest {

    @Test
    void theOrdonezDataIsTheRepositorysCopyByDefault() {
        Path repo = RepoFiles.root();
        EvalOptions o = EvalOptions.parse(new String[] {"A", "--no-readme"}, repo);
        assertEquals(RepoFiles.require("data", "ordonez"), o.ordonez());
    }

    @Test
    void anotherCopyIsReadWhenNamed() {
        EvalOptions o = EvalOptions.parse(new String[] {"B", "--ordonez", "/srv/ordonez"}, RepoFiles.root());
        assertEquals(Path.of("/srv/ordonez"), o.ordonez());
    }
}
