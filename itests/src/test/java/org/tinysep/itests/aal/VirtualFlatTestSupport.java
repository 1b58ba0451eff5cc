package org.tinysep.itests.aal;

import java.io.IOException;
import java.time.temporal.ChronoUnit;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;

/**
 * Builds a {@link VirtualFlat}: places simulated AmICA nodes in rooms and connects the flat's probes to each device
 * only after the AAL services consuming it have connected (so the probes hear every report last).
 */
abstract class VirtualFlatTestSupport extends AalTestSupport {

    static final String FLAT_OCCUPANCY = "FlatOccupancy";
    static final String FOLLOW_ME = "FollowMeLight";
    static final String INACTIVITY = "InactivityRecognition";

    /** Starts the flat's virtual time at midnight of tomorrow (UTC). */
    VirtualFlat virtualFlat(SyncPeer sync, long denseSeconds) throws IOException {
        TimeControllerProvider clock = awaitService(TimeControllerProvider.class, null, TIMEOUT);
        return new VirtualFlat(sync, clock, tomorrow().truncatedTo(ChronoUnit.DAYS), denseSeconds);
    }

    /** Place lights first: the Follow Me Light device only exists once there is a light. */
    SimulatedLight light(VirtualFlat flat, AmicaNode node, String room) throws IOException {
        SimulatedLight light = new SimulatedLight(room + " light", node, flat::now, flat.commands);
        Device d = place(node, "AmicaSimpleLight", room);
        SimpleLightProvider p = awaitService(SimpleLightProvider.class, uid(d), TIMEOUT);
        awaitConsumers(d, FOLLOW_ME);
        flat.watch(light, p, d);
        light.start(); // its first report (off) is a change its listeners hear: not a confirmation of a command
        flat.takeFirstReport(light);
        return light;
    }

    void motionSensor(VirtualFlat flat, AmicaNode node, String room) throws IOException {
        Device d = place(node, "AmicaMovement", room);
        awaitConsumers(d, FLAT_OCCUPANCY, FOLLOW_ME, INACTIVITY);
        flat.watch(awaitService(MovementProvider.class, uid(d), TIMEOUT));
    }

    void doorSensor(VirtualFlat flat, AmicaNode node, String room) throws IOException {
        Device d = place(node, "AmicaDoor", room);
        awaitConsumers(d, FLAT_OCCUPANCY, INACTIVITY);
        flat.watch(awaitService(DoorProvider.class, uid(d), TIMEOUT));
    }

    void petCollar(VirtualFlat flat, AmicaNode node, String room) throws IOException {
        Device d = place(node, "AmicaPetMovement", room);
        awaitConsumers(d, FOLLOW_ME);
        flat.watch(awaitService(PetMovementProvider.class, uid(d), TIMEOUT));
    }

    /** Waits until the devices of those drivers consume an interface of {@code provider}. */
    void awaitConsumers(Device provider, String... driverNames) {
        for (String driver : driverNames) {
            Device consumer = awaitService(Device.class, "(" + DeviceProperties.DRIVER_NAME + "=" + driver + ")",
                    TIMEOUT);
            await(TIMEOUT, () -> consumer.connections().stream()
                    .anyMatch(c -> c.providerDeviceUid().equals(provider.uid())),
                    driver + " to connect to " + provider.name());
        }
    }

    static String uid(Device d) {
        return "(" + DeviceProperties.DEVICE_UID + "=" + d.uid() + ")";
    }
}
