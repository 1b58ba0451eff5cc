package org.tinysep.amica.window.internal;

import java.util.Optional;
import org.tinysep.api.sensor.Coordinates;

/** The text form of a window position, {@code x,y,z} in metres; round-trips through the {@code position} parameter. */
final class Positions {

    private Positions() {
    }

    /**
     * @param text {@code x,y,z} in metres (spaces allowed), or blank for "no position"
     * @throws IllegalArgumentException naming the expected form and the value
     */
    static Optional<Coordinates> parse(String text) {
        if (text == null || text.isBlank()) {
            return Optional.empty();
        }
        String[] parts = text.split(",", -1);
        if (parts.length == 3) {
            try {
                double x = Double.parseDouble(parts[0].strip());
                double y = Double.parseDouble(parts[1].strip());
                double z = Double.parseDouble(parts[2].strip());
                if (Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) {
                    return Optional.of(new Coordinates(x, y, z));
                }
            } catch (NumberFormatException e) {
                // reported below
            }
        }
        throw new IllegalArgumentException("position must be x,y,z in metres (e.g. 2.5,0,1.2) or empty for none, was '"
                + text + "'");
    }

    /** @return {@code x,y,z}, or empty for no position */
    static String format(Optional<Coordinates> position) {
        return position.map(c -> c.x() + "," + c.y() + "," + c.z()).orElse("");
    }
}
