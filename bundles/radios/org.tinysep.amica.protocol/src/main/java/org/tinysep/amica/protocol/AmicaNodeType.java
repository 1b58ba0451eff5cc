package org.tinysep.amica.protocol;

import java.util.Collection;
import java.util.Collections;
import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;
import org.tinysep.link.frame.TypeCode;

/**
 * The AmICA node types and their bits in a keep-alive's product id. A node may have several types, so the product id
 * is a bit mask. Bits 0 to 7 are the thesis's types; bits 8 to 11 are a TinySEP extension: presence
 * nodes (a bed or seat mat, a toilet flush, an appliance in use) that report ON/OFF with the Reed-Switch Status
 * payload (A = 1 ON). Bits 12 to 15 are reserved and ignored. {@link #typeName()} is the matching node type name of
 * the TinySEP API ({@code org.tinysep.api.device.NodeType}): the constant's name in lower case with '-' for '_', as
 * the API constant of the same name is.
 */
public enum AmicaNodeType {

    /** Movement sensor, bit 0. */
    MOVEMENT(0),
    /** Reed switch on a door, bit 1. */
    DOOR(1),
    /** Reed switch on a window, bit 2. */
    WINDOW(2),
    /** Light with adjustable brightness, bit 3. */
    DIMMABLE_LIGHT(3),
    /** Heater, bit 4. */
    HEATER(4),
    /** Speaker, bit 5. */
    SPEAKER(5),
    /** Pet collar (pet movement), bit 6. */
    PET_COLLAR(6),
    /** On/off light, bit 7. */
    SIMPLE_LIGHT(7),
    /** TinySEP extension: pressure mat in or under a bed (ON while someone lies on it), bit 8. */
    PRESENCE_BED(8),
    /** TinySEP extension: pressure mat on a seat or sofa (ON while someone sits on it), bit 9. */
    PRESENCE_SEAT(9),
    /** TinySEP extension: toilet flush (ON while it is used), bit 10. */
    PRESENCE_FLUSH(10),
    /** TinySEP extension: appliance in use, e.g. a microwave or a toaster (ON while it runs), bit 11. */
    PRESENCE_APPLIANCE(11);

    /** The bit index and the type name (the constant's name); the lookup by name is the shared {@link TypeCode}'s. */
    private final TypeCode wire;

    AmicaNodeType(int bitIndex) {
        this.wire = TypeCode.named(this, bitIndex);
    }

    /** @return this type's bit mask in the product id, e.g. {@code 0x02} for {@link #DOOR} */
    public int bit() {
        return 1 << wire.code();
    }

    /** @return the position of this type's bit in the product id, 0..11 */
    public int bitIndex() {
        return wire.code();
    }

    /** @return the TinySEP node type name, e.g. {@code "dimmable-light"} */
    public String typeName() {
        return wire.typeName();
    }

    /**
     * @param productId a keep-alive's product id, 0..65535
     * @return the node types whose bits are set (unmodifiable); reserved bits (12..15) are ignored
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

    /** @return true for the TinySEP presence extension (bits 8..11): a node that reports ON/OFF as Reed-Switch Status */
    public boolean isPresence() {
        return bitIndex() >= PRESENCE_BED.bitIndex() && bitIndex() <= PRESENCE_APPLIANCE.bitIndex();
    }

    /**
     * @param typeName a TinySEP node type name, e.g. {@code "door"}
     * @return the AmICA node type with that name, if any
     */
    public static Optional<AmicaNodeType> fromTypeName(String typeName) {
        return TypeCode.byTypeName(values(), t -> t.wire, typeName);
    }
}
