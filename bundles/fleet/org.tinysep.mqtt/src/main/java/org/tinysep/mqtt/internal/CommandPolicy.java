package org.tinysep.mqtt.internal;

import java.util.Locale;

/** Which commands of one kind (acknowledgements, actuators) the bridge carries out (docs/mqtt.md, "Commands"). */
enum CommandPolicy {
    /** none: every such command is refused */
    OFF,
    /** only those signed with the flat's key (HMAC-SHA256, fresh, not replayed) */
    SIGNED,
    /** any, signed or not: anyone who may publish to the flat's command topics may act (not recommended) */
    UNSIGNED;

    static CommandPolicy parse(String key, String value) {
        try {
            return valueOf(value.strip().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(key + " must be off, signed or unsigned, was '" + value + "'");
        }
    }

    String word() {
        return name().toLowerCase(Locale.ROOT);
    }
}
