package org.tinysep.simulator.flat;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Loads a flat from a folder holding {@code house.xml} and {@code nodes.txt}, or a built-in flat by name
 * ({@code flat-a}) from the class path folder {@code /flats/<name>/}.
 */
public final class FlatLoader {

    private FlatLoader() {
    }

    public static Flat load(String dirOrName) throws IOException {
        Path dir = Path.of(dirOrName);
        if (Files.isDirectory(dir)) {
            return load(dir.getFileName().toString(), Files.readAllBytes(dir.resolve("house.xml")),
                    dir.resolve("house.xml").toString(), Files.readString(dir.resolve("nodes.txt")),
                    dir.resolve("nodes.txt").toString());
        }
        String base = "/flats/" + dirOrName + "/";
        byte[] house = resource(base + "house.xml", dirOrName);
        String nodes = new String(resource(base + "nodes.txt", dirOrName), StandardCharsets.UTF_8);
        return load(dirOrName, house, base + "house.xml", nodes, base + "nodes.txt");
    }

    public static Flat load(String name, byte[] houseXml, String houseSource, String nodes, String nodesSource)
            throws IOException {
        House house = House.read(new ByteArrayInputStream(houseXml), houseSource);
        return new Flat(name, house, NodeLayout.parse(nodes, nodesSource, house));
    }

    /** @return the built-in house XML of a flat, e.g. to install it as the platform's {@code var/house.xml} */
    public static byte[] resource(String path, String flat) throws IOException {
        try (InputStream in = FlatLoader.class.getResourceAsStream(path)) {
            if (in == null) {
                throw new IOException("no folder and no built-in flat named '" + flat + "' (built in: flat-a)");
            }
            return in.readAllBytes();
        }
    }
}
