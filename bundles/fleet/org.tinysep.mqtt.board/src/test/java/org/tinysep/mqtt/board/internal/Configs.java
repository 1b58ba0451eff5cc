package org.tinysep.mqtt.board.internal;

import java.lang.reflect.Proxy;
import java.util.Map;

/** A {@link BoardConfig} as ConfigAdmin + DS would make it: the given values, the annotation's defaults otherwise. */
final class Configs {

    private Configs() {
    }

    static BoardConfig board(Map<String, Object> values) {
        return (BoardConfig) Proxy.newProxyInstance(BoardConfig.class.getClassLoader(), new Class<?>[] {BoardConfig.class},
                (proxy, method, args) -> switch (method.getName()) {
                    case "annotationType" -> BoardConfig.class;
                    case "toString" -> "BoardConfig" + values;
                    case "hashCode" -> values.hashCode();
                    case "equals" -> proxy == args[0];
                    default -> values.getOrDefault(method.getName(), method.getDefaultValue());
                });
    }
}
