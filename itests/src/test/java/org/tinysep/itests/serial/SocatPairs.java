package org.tinysep.itests.serial;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.tinysep.testsupport.serial.SocatPair;

/** The socat pairs of one test, each in its own temp folder; {@link #close()} kills them and removes the folders. */
final class SocatPairs implements AutoCloseable {

    private final List<SocatPair> pairs = new ArrayList<>();
    private final List<Path> dirs = new ArrayList<>();

    /** @return a started pair with link paths {@code <new temp folder>/a} and {@code /b} */
    SocatPair start() throws IOException, InterruptedException {
        Path dir = Files.createTempDirectory("tinysep-serial-");
        dirs.add(dir);
        SocatPair pair = new SocatPair(dir).start();
        pairs.add(pair);
        return pair;
    }

    @Override
    public void close() throws IOException, InterruptedException {
        for (SocatPair p : pairs) {
            p.kill();
        }
        for (Path dir : dirs) {
            try (Stream<Path> files = Files.list(dir)) {
                for (Path f : files.toList()) {
                    Files.deleteIfExists(f);
                }
            }
            Files.deleteIfExists(dir);
        }
    }
}
