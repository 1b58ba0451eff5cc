package org.tinysep.sunspot.protocol;

import java.util.Optional;
import org.tinysep.link.frame.TypeCode;

/**
 * The Sun SPOT sensor types: the header's sensor type byte, which is also the first byte of the payloads of thesis
 * Table 3.2. {@link #typeName()} is the matching node type name of the TinySEP API
 * ({@code org.tinysep.api.device.NodeType}).
 */
public enum SunSpotSensorType {

    /** Movement sensor node (accelerometer), code 2. */
    MOVEMENT(2, "movement"),
    /** Temperature sensor node, code 3. */
    TEMPERATURE(3, "temperature"),
    /** Light sensor node (brightness only, no actuator), code 4. */
    LIGHT(4, "light-sensor"),
    /** Pet collar (pet movement), code 5. */
    PET_COLLAR(5, "pet-collar"),
    /** Person node: a Sun SPOT worn by a person; buttons, movement summaries, bursts. Code 6. Since 2.2. */
    PERSON(6, "person");

    /** The sensor type byte and the type name; the lookups are the shared {@link TypeCode}'s. */
    private final TypeCode wire;

    SunSpotSensorType(int code, String typeName) {
        this.wire = new TypeCode(code, typeName);
    }

    /** @return the sensor type byte, e.g. 3 for {@link #TEMPERATURE} */
    public int code() {
        return wire.code();
    }

    /** @return the TinySEP node type name, e.g. {@code "light-sensor"} */
    public String typeName() {
        return wire.typeName();
    }

    /**
     * @param code a sensor type byte (any int)
     * @return the sensor type with that code, if any
     */
    public static Optional<SunSpotSensorType> fromCode(int code) {
        return TypeCode.byCode(values(), t -> t.wire, code);
    }

    /** @return true if {@code code} is one of the sensor types (2..6), without allocating */
    static boolean isKnown(int code) {
        return code >= MOVEMENT.code() && code <= PERSON.code();
    }

    /**
     * @param typeName a TinySEP node type name, e.g. {@code "temperature"}
     * @return the sensor type with that name, if any
     */
    public static Optional<SunSpotSensorType> fromTypeName(String typeName) {
        return TypeCode.byTypeName(values(), t -> t.wire, typeName);
    }
}
