package org.tinysep.simulator.replay;

import java.util.Objects;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;

/**
 * The simulated node a recorded sensor becomes. Only the AmICA family is supported so far.
 *
 * @param sensor   recorded sensor name
 * @param family   node family, always {@value #AMICA} for now
 * @param address  node address {@code NG.ADDR}
 * @param type     node type announced in the keep-alive's product id: movement, pet-collar, door, window or a
 *                 presence type (presence-bed, presence-seat, presence-flush, presence-appliance: the TinySEP
 *                 extension, bits 8..11; such a node sends Reed-Switch Status, A = 1 while the sensor is ON)
 * @param room     room name the node is placed in (House Information room name)
 * @param doorKind for {@code door} nodes the Door device's {@code kind} parameter, {@code OUTER} or {@code INNER};
 *                 empty for other types
 * @param name     device name to show, e.g. {@code Fridge (Magnetic)}
 */
public record NodeSpec(String sensor, String family, AmicaAddress address, AmicaNodeType type, String room,
                       String doorKind, String name) {

    /** The AmICA family name. */
    public static final String AMICA = "amica";

    /** The node types a recorded binary sensor can become, for messages. */
    static final String REPLAYABLE = "movement, pet-collar, door, window, presence-bed, presence-seat, "
            + "presence-flush or presence-appliance";

    /** @throws NullPointerException if a field is null; IllegalArgumentException for an unsupported combination */
    public NodeSpec {
        Objects.requireNonNull(sensor, "sensor");
        Objects.requireNonNull(family, "family");
        Objects.requireNonNull(address, "address");
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(room, "room");
        Objects.requireNonNull(doorKind, "doorKind");
        Objects.requireNonNull(name, "name");
        if (!AMICA.equals(family)) {
            throw new IllegalArgumentException("node family '" + family + "' is not supported; only amica");
        }
        if (!isReplayable(type)) {
            throw new IllegalArgumentException("node type '" + type.typeName()
                    + "' cannot replay a binary sensor; use " + REPLAYABLE);
        }
        if (type == AmicaNodeType.DOOR != (doorKind.equals("OUTER") || doorKind.equals("INNER"))) {
            throw new IllegalArgumentException("doorKind '" + doorKind
                    + "': door nodes need OUTER or INNER, other types none");
        }
    }

    /** @return true if the node sends motion reports (movement, pet-collar), false for reed switches */
    public boolean isMotion() {
        return type == AmicaNodeType.MOVEMENT || type == AmicaNodeType.PET_COLLAR;
    }

    static boolean isReplayable(AmicaNodeType type) {
        return type == AmicaNodeType.MOVEMENT || type == AmicaNodeType.PET_COLLAR
                || type == AmicaNodeType.DOOR || type == AmicaNodeType.WINDOW || type.isPresence();
    }
}
