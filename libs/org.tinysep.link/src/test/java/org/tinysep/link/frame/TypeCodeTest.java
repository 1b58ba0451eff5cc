package org.tinysep.link.frame;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The type table lookups and the typed reason of both families, on a toy family: a reason enum, its exception
 * (declaration and constructor only, as {@code AmicaProtocolException} is) and a type enum holding a
 * {@link TypeCode} per constant, as {@code AmicaNodeType} and {@code SunSpotSensorType} do.
 */
class TypeCodeTest {

    enum Reason { BAD }

    static final class ToyException extends ProtocolException implements ProtocolException.Typed<Reason> {
        private static final long serialVersionUID = 1L;

        ToyException(Reason reason, String detail) {
            super(reason, "bad", detail);
        }
    }

    enum Toy {
        A(7, "a-type"), B(9, "b-type"), C(7, "c-type");

        private final TypeCode wire;

        Toy(int code, String typeName) {
            this.wire = new TypeCode(code, typeName);
        }
    }

    enum Named {
        DIMMABLE_LIGHT, DOOR
    }

    @Test
    void aNamedEntryTakesTheConstantsNameInLowerCaseWithDashes() {
        assertEquals(new TypeCode(3, "dimmable-light"), TypeCode.named(Named.DIMMABLE_LIGHT, 3));
        assertEquals(new TypeCode(1, "door"), TypeCode.named(Named.DOOR, 1));
    }

    @Test
    void byCodeFindsTheFirstConstantWithThatNumber() {
        assertEquals(Optional.of(Toy.A), TypeCode.byCode(Toy.values(), t -> t.wire, 7));
        assertEquals(Optional.of(Toy.B), TypeCode.byCode(Toy.values(), t -> t.wire, 9));
        assertEquals(Optional.empty(), TypeCode.byCode(Toy.values(), t -> t.wire, 8));
    }

    @Test
    void byTypeNameFindsTheConstantWithThatName() {
        assertEquals(Optional.of(Toy.C), TypeCode.byTypeName(Toy.values(), t -> t.wire, "c-type"));
        assertEquals(Optional.empty(), TypeCode.byTypeName(Toy.values(), t -> t.wire, "A"));
        assertEquals(Optional.empty(), TypeCode.byTypeName(Toy.values(), t -> t.wire, null));
    }

    @Test
    void aFamilysExceptionInheritsItsTypedReasonAndTheSharedMessage() {
        ToyException e = new ToyException(Reason.BAD, "byte 3");
        Reason typed = e.reason(); // compiles only if reason() is typed by the family's enum
        assertSame(Reason.BAD, typed);
        assertEquals("BAD (bad): byte 3", e.getMessage());
        assertEquals(0, e.getStackTrace().length);
        assertNull(e.getCause());
    }
}
