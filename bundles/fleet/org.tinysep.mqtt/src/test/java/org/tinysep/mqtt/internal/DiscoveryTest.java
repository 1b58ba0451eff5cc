package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Home Assistant discovery configs that Home Assistant 2024.3 accepts (scripts/ha-check.sh found the refusal): a
 * device without a room (a pet collar moves with the pet) has no {@code suggested_area} at all, since Home
 * Assistant refuses the whole config for {@code "suggested_area": null}.
 */
class DiscoveryTest {

    private final Discovery discovery = new Discovery(new Topics("tinysep", "flat-a", "homeassistant"));

    @Test
    void aDeviceWithoutARoomHasNoSuggestedArea() {
        String config = discovery.device("collar-1", DeviceKind.PET_MOVEMENT, "Pet collar 1.20", "").text();
        assertFalse(config.contains("suggested_area"), config);
        assertTrue(config.contains("\"device_class\":\"motion\""), config);
    }

    @Test
    void aDeviceInARoomSuggestsIt() {
        String config = discovery.device("move-1", DeviceKind.MOVEMENT, "Movement 1.17", "Kitchen").text();
        assertTrue(config.contains("\"suggested_area\":\"Kitchen\""), config);
    }
}
