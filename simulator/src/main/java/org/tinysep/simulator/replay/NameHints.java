package org.tinysep.simulator.replay;

import java.util.regex.Pattern;
import org.tinysep.amica.protocol.AmicaNodeType;

/**
 * What the built-in defaults read from a recorded sensor's name and room when the mapping file says nothing about
 * the sensor (a recorded home replayed without a mapping file must still have an outer door and beds).
 * Only two decisions, both where the kind alone cannot tell and a wrong guess is costly:
 * <ul>
 * <li>a door whose name says it leads outside ({@code Frontdoor}, {@code Main door}, {@code Entrance},
 * {@code Back door}, {@code Garden door}, {@code Exit}, ...) or that sits in an entrance room ({@code Entrance},
 * {@code Entry}, {@code Porch}, {@code Foyer}, {@code Vestibule}) is {@code OUTER}: without an outer door Flat
 * Occupancy never sees the resident leave, and the alert watches an empty flat;</li>
 * <li>a pressure mat whose name or room says bed ({@code Bed}, {@code Bedroom}) is {@code presence-bed}, unless its
 * name says seat ({@code Chair}, {@code Sofa}, {@code Couch}, {@code Seat}, {@code Bench}, {@code Stool}): a bed mat
 * taken for a seat loses the sleep state.</li>
 * </ul>
 * Everything else keeps the default of its kind. A mapping file that names the sensor, or changes the kind's
 * default, decides instead.
 */
final class NameHints {

    private static final Pattern OUTER_NAME = Pattern.compile(
            "front|main ?door|maindoor|entrance|entry|outer|outside|exit|street|garden|porch|back ?door",
            Pattern.CASE_INSENSITIVE);
    private static final Pattern OUTER_ROOM = Pattern.compile("entrance|entry|porch|foyer|vestibule",
            Pattern.CASE_INSENSITIVE);
    private static final Pattern BED = Pattern.compile("bed", Pattern.CASE_INSENSITIVE);
    private static final Pattern SEAT = Pattern.compile("seat|chair|sofa|couch|bench|stool",
            Pattern.CASE_INSENSITIVE);

    private NameHints() {
    }

    /** @return {@code OUTER} or {@code INNER} for a door the mapping file does not describe */
    static String doorKind(String sensor, String room) {
        return OUTER_NAME.matcher(sensor).find() || OUTER_ROOM.matcher(room).find() ? "OUTER" : "INNER";
    }

    /** @return the presence node type for a pressure mat the mapping file does not describe */
    static AmicaNodeType pressureType(String sensor, String room) {
        boolean bed = BED.matcher(sensor).find() || BED.matcher(room).find();
        return bed && !SEAT.matcher(sensor).find() ? AmicaNodeType.PRESENCE_BED : AmicaNodeType.PRESENCE_SEAT;
    }
}
