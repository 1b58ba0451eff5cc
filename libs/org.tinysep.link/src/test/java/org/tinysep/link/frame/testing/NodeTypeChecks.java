package org.tinysep.link.frame.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Map;
import java.util.Optional;
import java.util.function.Function;

/** Checks both protocol families' tests make of their node type enums against the API's node type names. */
public final class NodeTypeChecks {

    private NodeTypeChecks() {
    }

    /**
     * Each type's name is the API constant ({@code org.tinysep.api.device.NodeType}) of the same name, or the one
     * {@code renamed} names; {@code fromTypeName} maps that name back to the type.
     *
     * @param api     the API's class of node type constants
     * @param renamed the types whose API constant has another name, e.g. Sun SPOT LIGHT: LIGHT_SENSOR
     */
    public static <T extends Enum<T>> void assertNamedAsTheApi(T[] types, Function<T, String> typeName,
            Function<String, Optional<T>> fromTypeName, Class<?> api, Map<T, String> renamed) {
        for (T t : types) {
            String expected = renamed.containsKey(t) ? renamed.get(t) : apiConstant(api, t.name());
            assertEquals(expected, typeName.apply(t), t.name());
            assertEquals(Optional.of(t), fromTypeName.apply(expected));
        }
    }

    private static String apiConstant(Class<?> api, String name) {
        try {
            return (String) api.getField(name).get(null);
        } catch (ReflectiveOperationException e) {
            return fail("no API node type name for " + name + ": " + e);
        }
    }
}
