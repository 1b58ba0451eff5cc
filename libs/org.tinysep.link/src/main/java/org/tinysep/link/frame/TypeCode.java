package org.tinysep.link.frame;

import java.util.Locale;
import java.util.Optional;
import java.util.function.Function;

/**
 * One entry of a family's node type table: the type's number on the wire (the AmICA product id's bit index, the Sun
 * SPOT sensor type byte) and the matching TinySEP node type name ({@code org.tinysep.api.device.NodeType}). Each
 * family's enum ({@code AmicaNodeType}, {@code SunSpotSensorType}) holds one per constant and looks its constants up
 * with {@link #byCode} and {@link #byTypeName}, written once here.
 *
 * @param code     the number on the wire
 * @param typeName the TinySEP node type name, e.g. {@code "door"}
 */
public record TypeCode(int code, String typeName) {

    /**
     * The entry of a constant whose TinySEP node type name follows the API's rule: the constant's name in lower case
     * with '-' for '_' ({@code DIMMABLE_LIGHT} is {@code "dimmable-light"}), as every AmICA type's is.
     *
     * @param constant the family's constant (its name is set in its constructor already)
     * @param code     the number on the wire
     */
    public static TypeCode named(Enum<?> constant, int code) {
        return new TypeCode(code, constant.name().toLowerCase(Locale.ROOT).replace('_', '-'));
    }

    /**
     * @param types  the family's constants, e.g. {@code values()}
     * @param codeOf a constant's entry
     * @param code   the number looked for (any int)
     * @return the first constant with that number, if any
     */
    public static <E> Optional<E> byCode(E[] types, Function<E, TypeCode> codeOf, int code) {
        for (E t : types) {
            if (codeOf.apply(t).code == code) {
                return Optional.of(t);
            }
        }
        return Optional.empty();
    }

    /**
     * @param types    the family's constants, e.g. {@code values()}
     * @param codeOf   a constant's entry
     * @param typeName the TinySEP node type name looked for
     * @return the first constant with that name, if any
     */
    public static <E> Optional<E> byTypeName(E[] types, Function<E, TypeCode> codeOf, String typeName) {
        for (E t : types) {
            if (codeOf.apply(t).typeName.equals(typeName)) {
                return Optional.of(t);
            }
        }
        return Optional.empty();
    }
}
