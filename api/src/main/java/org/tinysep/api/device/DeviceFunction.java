package org.tinysep.api.device;

import java.util.Objects;

/**
 * A named action a user can invoke on a device (thesis getAllFunctions/loadFunctions).
 *
 * @param name        the name passed to {@link Device#invoke(String)}
 * @param description one line for the user
 */
public record DeviceFunction(String name, String description) {

    public DeviceFunction {
        Objects.requireNonNull(name, "name");
        description = description == null ? "" : description;
    }
}
