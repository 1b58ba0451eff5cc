package org.tinysep.web.api.internal;

import java.util.Locale;
import java.util.Optional;

/** The two kinds of console user: the installer may do everything, the caregiver may read (and acknowledge). */
public enum Role {
    INSTALLER,
    CAREGIVER;

    /** @return the name users type: {@code installer} or {@code caregiver} */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @return the role named {@code text} (case ignored), if any */
    public static Optional<Role> parse(String text) {
        if (text == null) {
            return Optional.empty();
        }
        for (Role r : values()) {
            if (r.id().equalsIgnoreCase(text.strip())) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }
}
