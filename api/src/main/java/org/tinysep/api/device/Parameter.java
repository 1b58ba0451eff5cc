package org.tinysep.api.device;

import java.util.Objects;

/**
 * One configuration parameter or read-only figure of a device or driver.
 *
 * @param key         the key used by {@link Device#setParameter(String, String)}
 * @param value       the current value as text; empty when unset
 * @param writable    whether the user may change it
 * @param description one line for the user
 */
public record Parameter(String key, String value, boolean writable, String description) {

    public Parameter {
        Objects.requireNonNull(key, "key");
        value = value == null ? "" : value;
        description = description == null ? "" : description;
    }

    public static Parameter readOnly(String key, Object value, String description) {
        return new Parameter(key, value == null ? "" : value.toString(), false, description);
    }

    public static Parameter writable(String key, Object value, String description) {
        return new Parameter(key, value == null ? "" : value.toString(), true, description);
    }
}
