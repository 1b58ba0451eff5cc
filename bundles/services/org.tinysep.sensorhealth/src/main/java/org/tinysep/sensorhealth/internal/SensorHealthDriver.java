package org.tinysep.sensorhealth.internal;

import java.time.DateTimeException;
import java.time.Duration;
import java.time.ZoneId;
import java.util.function.Function;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.AbstractDriver;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.time.PlatformTicker;

/**
 * Sensor Health: creates its single device at once. It watches every bus device's node health, tells
 * caregivers by a notice (a lower-priority mail than an inactivity alert) when a sensor stays silent or its battery
 * runs low, and offers {@code SensorHealthProvider}: which rooms are unmonitored.
 */
@Component(service = {}, immediate = true, configurationPid = SensorHealthDriver.PID)
@Designate(ocd = SensorHealthConfig.class)
public final class SensorHealthDriver extends AbstractDriver {

    static final String PID = "org.tinysep.sensorhealth";
    static final String NAME = "SensorHealth";

    private NodeView view;
    private ServiceTracker<MailManagerProvider, MailManagerProvider> mail;
    private volatile PlatformTicker ticker;

    public SensorHealthDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, SensorHealthConfig config) {
        start(bundleContext);
        RoomDirectory rooms = context().rooms();
        Function<String, String> roomName = uid -> rooms.room(uid).map(Room::name).orElse(uid);
        NodeIndex index = new NodeIndex(new Notices(Duration.ofMinutes(Math.max(0, config.noticeAfterMinutes()))),
                roomName);
        index.whenQueued(() -> {
            PlatformTicker t = ticker;
            if (t != null) {
                t.wakeNext(); // a node came, changed or went: the next tick applies it
            }
        });
        view = new NodeView(bundleContext, index);
        mail = new ServiceTracker<>(bundleContext, MailManagerProvider.class, null);
        mail.open();
        SensorHealthDevice device = addDevice(new SensorHealthDevice(context(), index, roomName,
                new NoticeWords(zone(config)), mail::getService, config));
        ticker = PlatformTicker.whenDue(bundleContext, "sensor-health", device::tick);
    }

    private ZoneId zone(SensorHealthConfig config) {
        String id = config.timeZone();
        if (id == null || id.isBlank()) {
            return ZoneId.systemDefault();
        }
        try {
            return ZoneId.of(id.strip());
        } catch (DateTimeException e) {
            context().event(EventKind.PROBLEM, "timeZone '" + id + "' is not a time zone (" + e.getMessage()
                    + "); notices use " + ZoneId.systemDefault());
            return ZoneId.systemDefault();
        }
    }

    @Deactivate
    void deactivate() {
        ticker.close();
        stop();
        view.close();
        mail.close();
    }
}
