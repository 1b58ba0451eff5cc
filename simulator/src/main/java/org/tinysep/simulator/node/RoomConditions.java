package org.tinysep.simulator.node;

import java.util.ArrayList;
import java.util.List;

/**
 * Temperature and brightness of a room, for the Sun SPOT sensors: a daily curve (cooler at night, daylight from
 * 07:00 to 19:00) plus the room's simulated heaters and lights.
 */
final class RoomConditions {

    private final List<AmicaNode> actuators = new ArrayList<>();

    void add(AmicaNode n) {
        actuators.add(n);
    }

    /** @return tenths of a degree Celsius: 19.5 °C +- 1 °C over the day, + up to 3 °C from the room's heaters */
    int temperatureTenths(String room, long t) {
        double day = Math.sin(2 * Math.PI * (Math.floorMod(t, 86400) - 9 * 3600) / 86400.0);
        int heat = actuators.stream().filter(n -> n.spec().has("heater") && n.spec().room().equals(room))
                .mapToInt(AmicaNode::heater).max().orElse(0);
        return (int) Math.round(195 + 10 * day + 0.3 * heat);
    }

    /** @return percent: the brighter of daylight and the room's lights */
    int brightness(String room, long t) {
        long s = Math.floorMod(t, 86400);
        int daylight = s < 7 * 3600 || s > 19 * 3600 ? 0 : (int) Math.round(70 * Math.sin(Math.PI * (s - 7 * 3600) / (12 * 3600.0)));
        int lamps = actuators.stream().filter(n -> n.spec().room().equals(room)
                && (n.spec().has("simple-light") || n.spec().has("dimmable-light"))).mapToInt(AmicaNode::light).max().orElse(0);
        return Math.min(100, Math.max(daylight, lamps));
    }
}
