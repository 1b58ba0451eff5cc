package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import java.util.UUID;

/**
 * A House Information file (format of {@code org.tinysep.houseinformation}) for a recorded home that brings none:
 * one room per mapped room name, its type = its name (Inactivity Recognition then finds a type limit where the name
 * is a known type, e.g. {@code Bathroom}, and uses its default limit otherwise). No neighbour links: the data gives
 * no floor plan and the evaluation does not use them.
 */
final class HouseFile {

    private HouseFile() {
    }

    static Path write(Collection<String> rooms, Path file) throws IOException {
        StringBuilder x = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<HOUSE_ROOMS>\n");
        for (String r : rooms) {
            String uid = UUID.nameUUIDFromBytes(("room " + r).getBytes(java.nio.charset.StandardCharsets.UTF_8))
                    .toString();
            x.append("    <ROOM>\n        <UID>").append(uid).append("</UID>\n        <NAME>").append(esc(r))
                    .append("</NAME>\n        <TYPE>").append(esc(r)).append("</TYPE>\n        <NEIGHBORS/>\n    </ROOM>\n");
        }
        Files.writeString(file, x.append("</HOUSE_ROOMS>\n").toString());
        return file;
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
