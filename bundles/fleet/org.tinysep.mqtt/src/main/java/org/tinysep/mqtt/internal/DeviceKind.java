package org.tinysep.mqtt.internal;

import java.util.Optional;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.HeaterProvider;
import org.tinysep.api.actuator.PercentActuator;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.actuator.SpeakerProvider;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.LightBrightnessProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.sensor.TemperatureProvider;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.sensor.presence.PresenceProvider;

/**
 * The device interfaces the bridge publishes, in the order a device providing several is classified by (its first):
 * the {@code type} of its state, its Home Assistant component and device class, and the one parameter an MQTT
 * command may set (actuators only).
 */
enum DeviceKind {
    MOVEMENT(MovementProvider.class, "movement", "binary_sensor", "motion", null),
    PET_MOVEMENT(PetMovementProvider.class, "petmovement", "binary_sensor", "motion", null),
    DOOR(DoorProvider.class, "door", "binary_sensor", "door", null),
    WINDOW(WindowProvider.class, "window", "binary_sensor", "window", null),
    PRESENCE(PresenceProvider.class, "presence", "binary_sensor", "occupancy", null),
    TEMPERATURE(TemperatureProvider.class, "temperature", "sensor", "temperature", null),
    BRIGHTNESS(LightBrightnessProvider.class, "brightness", "sensor", null, null),
    LIGHT(SimpleLightProvider.class, "light", "light", null, "on"),
    DIMMABLE_LIGHT(DimmableLightProvider.class, "dimmablelight", "light", null, "brightness"),
    HEATER(HeaterProvider.class, "heater", "switch", null, "potency"),
    SPEAKER(SpeakerProvider.class, "speaker", "switch", null, "volume");

    final Class<?> providerType;
    final String type;
    final String component;
    final String deviceClass;
    /** the parameter an MQTT command may set, null for sensors */
    final String command;

    DeviceKind(Class<?> providerType, String type, String component, String deviceClass, String command) {
        this.providerType = providerType;
        this.type = type;
        this.component = component;
        this.deviceClass = deviceClass;
        this.command = command;
    }

    boolean actuator() {
        return command != null;
    }

    /** @return the value as JSON: a boolean (binary sensors, simple light), a number, or null while unknown */
    Object value(Object p) {
        return switch (this) {
            case MOVEMENT -> ((MovementProvider) p).lastMovement().map(MovementEvent::detected).orElse(null);
            case PET_MOVEMENT -> ((PetMovementProvider) p).lastMovement().map(MovementEvent::detected).orElse(null);
            case DOOR -> open(((DoorProvider) p).state());
            case WINDOW -> open(((WindowProvider) p).state());
            case PRESENCE -> ((PresenceProvider) p).present();
            case TEMPERATURE -> {
                var c = ((TemperatureProvider) p).celsius();
                yield c.isPresent() ? c.getAsDouble() : null;
            }
            case BRIGHTNESS -> percent(((LightBrightnessProvider) p).brightness());
            case LIGHT -> ((SimpleLightProvider) p).isOn().orElse(null);
            case DIMMABLE_LIGHT, HEATER, SPEAKER -> percent(((PercentActuator) p).level());
        };
    }

    /** @return the value in words for the explanation */
    String describe(Object value) {
        if (value == null) {
            return "no report yet";
        }
        return switch (this) {
            case MOVEMENT -> Boolean.TRUE.equals(value) ? "movement detected" : "no movement";
            case PET_MOVEMENT -> Boolean.TRUE.equals(value) ? "pet movement detected" : "no pet movement";
            case DOOR -> Boolean.TRUE.equals(value) ? "door open" : "door closed";
            case WINDOW -> Boolean.TRUE.equals(value) ? "window open" : "window closed";
            case PRESENCE -> Boolean.TRUE.equals(value) ? "someone is there" : "nobody there";
            case TEMPERATURE -> value + " °C";
            case BRIGHTNESS -> "brightness " + value + " %";
            case LIGHT -> Boolean.TRUE.equals(value) ? "light on" : "light off";
            case DIMMABLE_LIGHT -> "light at " + value + " %";
            case HEATER -> "heater at " + value + " %";
            case SPEAKER -> "volume " + value + " %";
        };
    }

    /** @return the parameter value of a plain {@code ON}/{@code OFF} command (Home Assistant's default payloads) */
    String onOff(boolean on) {
        return this == LIGHT ? Boolean.toString(on) : on ? "100" : "0";
    }

    private static Object open(OpenState s) {
        return s == OpenState.UNKNOWN ? null : s == OpenState.OPEN;
    }

    private static Object percent(Optional<Percent> p) {
        return p.map(Percent::value).orElse(null);
    }
}
