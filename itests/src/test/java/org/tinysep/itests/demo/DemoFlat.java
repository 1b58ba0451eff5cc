package org.tinysep.itests.demo;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** The simulator's flat A configured as {@code scripts/demo-flat.sh} does, for the tests that play its demo day. */
public final class DemoFlat {

    /** The simulator's flat A: its {@code house.xml} and {@code nodes.txt}. */
    public static final Path FLAT_A = Path.of("..", "simulator", "src", "main", "resources", "flats", "flat-a");

    private DemoFlat() {
    }

    /**
     * Puts an event log that holds the whole day, a copy of flat A's house file (in a new folder named after
     * {@code prefix}) and the placement of every node of flat A plus {@code more} ({@code address=room} each).
     */
    public static void configure(Map<String, Map<String, String>> configs, String prefix, String... more) {
        configs.put("org.tinysep.runtime", Map.of("eventCapacity", "500000"));
        try {
            Path house = Files.createTempDirectory(prefix).resolve("house.xml");
            Files.copy(FLAT_A.resolve("house.xml"), house, StandardCopyOption.REPLACE_EXISTING);
            configs.put("org.tinysep.houseinformation", Map.of("file", house.toString()));
            configs.put("org.tinysep.houseinformation.placement", Map.of("placements", placements(more)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@code address=room} for every node of flat A's nodes.txt except pet collars, then {@code more}. */
    private static String placements(String... more) throws IOException {
        List<String> entries = new ArrayList<>();
        for (String line : Files.readAllLines(FLAT_A.resolve("nodes.txt"))) {
            String[] f = line.strip().split("\\|", -1);
            if (line.strip().startsWith("#") || f.length < 5 || (f.length > 5 && f[5].contains("agent="))) {
                continue;
            }
            entries.add(f[2].strip() + "=" + f[4].strip());
        }
        entries.addAll(List.of(more));
        return String.join(", ", entries);
    }
}
