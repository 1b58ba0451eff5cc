package org.tinysep.followmelight.internal;

import java.time.Duration;
import java.time.Instant;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.device.support.lifecycle.AbstractDriver;
import org.tinysep.device.support.lifecycle.SingleDeviceWiring;
import org.tinysep.device.support.rooms.TrackedPlacements;
import org.tinysep.device.support.time.Due;
import org.tinysep.device.support.time.PlatformTicker;

/**
 * Follow Me Light driver: creates its single device when the first light (simple or dimmable) appears and
 * connects it to every later one; movement, pet movement, Flat Occupancy and House Information are connected
 * whenever present. A device left without lights is removed and created anew with the next light.
 */
@Component(service = {}, immediate = true, configurationPid = FollowMeDriver.PID)
@Designate(ocd = FollowMeConfig.class)
public final class FollowMeDriver extends AbstractDriver {

    static final String PID = "org.tinysep.followmelight";
    static final String NAME = "FollowMeLight";

    private volatile SingleDeviceWiring<FollowMeDevice> wiring;
    private Duration grace;
    private Percent brightness;
    private TrackedPlacements directory;
    private volatile PlatformTicker ticker;

    public FollowMeDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, FollowMeConfig config) {
        grace = Duration.ofSeconds(Math.min(3600, Math.max(5, config.graceSeconds())));
        brightness = Percent.of(Math.min(100, Math.max(1, config.brightness())));
        start(bundleContext);
        directory = new TrackedPlacements(bundleContext, this::lightMoved); // a device's room changed
        wiring = new SingleDeviceWiring<>(this, FollowMeDevice.class,
                this::device, FollowMeDevice::forget);
        wiring.optional(bundleContext, FlatOccupancyProvider.class, FollowMeDevice::use);
        wiring.optional(bundleContext, HouseInformationProvider.class, FollowMeDevice::use);
        wiring.optional(bundleContext, MovementProvider.class, FollowMeDevice::use);
        wiring.optional(bundleContext, PetMovementProvider.class, FollowMeDevice::use);
        wiring.source(bundleContext, SimpleLightProvider.class, (d, p) -> d.control(p));
        wiring.source(bundleContext, DimmableLightProvider.class, (d, p) -> d.control(p));
        ticker = PlatformTicker.whenDue(bundleContext, "follow-me-light", this::tick);
    }

    private FollowMeDevice device() {
        FollowMeDevice d = new FollowMeDevice(context(), directory, grace, brightness);
        d.whenDue(at -> {
            PlatformTicker t = ticker;
            if (t != null) {
                t.wake(at);
            }
        });
        return d;
    }

    /** A tick when a lit room's grace period ends; @return the next such end, null while no room is lit */
    private Instant tick(Instant now) {
        Instant next = null;
        for (FollowMeDevice d : wiring.current()) {
            Instant due = d.tick(now);
            next = Due.earliest(next, due);
        }
        return next;
    }

    @Deactivate
    void deactivate() {
        ticker.close();
        wiring.close();
        stop();
        directory.close();
    }

    /** A device was placed, moved or unplaced: if it is a light, the device (if there is one yet) files it anew. */
    private void lightMoved(String uid) {
        SingleDeviceWiring<FollowMeDevice> w = wiring;
        if (w != null) {
            w.current().forEach(d -> d.lightMoved(uid));
        }
    }
}
