package org.tinysep.amica.protocol;

import java.util.Collection;
import java.util.Collections;
import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;

/**
 * The AmICA node types and their bits in a keep-alive's product id. A node may have several types, so the product id
 * is a bit mask; bits 8 to 15 are reserved and ignored. {@link #typeName()} is the matching node type name of the
 * TinySEP API ({@code org.tinysep.api.device.NodeType}).
 */
public enum AmicaNodeType {

    /** Movement sensor, bit 0. */
    MOVEMENT(0, "movement"),
    /** Reed switch on a door, bit 1. */
    DOOR(1, "door"),
    /** Reed switch on a window, bit 2. */
    WINDOW(2, "window"),
    /** Light with adjustable brightness, bit 3. */
    DIMMABLE_LIGHT(3, "dimmable-light"),
    /** Heater, bit 4. */
    HEATER(4, "heater"),
    /** Speaker, bit 5. */
    SPEAKER(5, "speaker"),
    /** Pet collar (pet movement), bit 6. */
    PET_COLLAR(6, "pet-collar"),
    /** On/off light, bit 7. */
    SIMPLE_LIGHT(7, "simple-light");

    private final int bitIndex;
    private final String typeName;

    AmicaNodeType(int bitIndex, String typeName) {
        this.bitIndex = bitIndex;
        this.typeName = typeName;
    }

    /** @return this type's bit mask in the product id, e.g. {@code 0x02} for {@link #DOOR} */
    public int bit() {
        return 1 << bitIndex;
    }

    /** @return the position of this type's bit in the product id, 0..7 */
    public int bitIndex() {
        return bitIndex;
    }

    /** @return the TinySEP node type name, e.g. {@code "dimmable-light"} */
    public String typeName() {
        return typeName;
    }

    /**
     * @param productId a keep-alive's product id, 0..65535
     * @return the node types whose bits are set (unmodifiable); reserved bits are ignored
     * @throws IllegalArgumentException if productId is outside 0..65535
     */
    public static Set<AmicaNodeType> fromProductId(int productId) {
        if (productId < 0 || productId > 0xFFFF) {
            throw new IllegalArgumentException("productId " + productId + " is outside 0..65535");
        }
        EnumSet<AmicaNodeType> types = EnumSet.noneOf(AmicaNodeType.class);
        for (AmicaNodeType t : values()) {
            if ((productId & t.bit()) != 0) {
                types.add(t);
            }
        }
        return Collections.unmodifiableSet(types);
    }

    /**
     * @param types node types (duplicates allowed)
     * @return the product id with exactly these types' bits set
     */
    public static int productId(Collection<AmicaNodeType> types) {
        int id = 0;
        for (AmicaNodeType t : types) {
            id |= t.bit();
        }
        return id;
    }

    /**
     * @param typeName a TinySEP node type name, e.g. {@code "door"}
     * @return the AmICA node type with that name, if any
     */
    public static Optional<AmicaNodeType> fromTypeName(String typeName) {
        for (AmicaNodeType t : values()) {
            if (t.typeName.equals(typeName)) {
                return Optional.of(t);
            }
        }
        return Optional.empty();
    }
}
