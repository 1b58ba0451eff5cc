package org.tinysep.falldetection.internal;

import java.time.DateTimeException;
import java.time.ZoneId;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * Fall Detection: listens to every person node and raises a FALL alert through the alert service when
 * one reports a fall ({@link FallDetector}). Each node has its own detector; the radio's thread calls in, and the
 * work per report is a few hundred multiplications, so no executor is needed.
 */
@Component(service = {}, immediate = true, configurationPid = FallDetection.PID)
@Designate(ocd = FallDetectionConfig.class)
public final class FallDetection {

    static final String PID = "org.tinysep.falldetection";
    /** The source the alert service knows these alerts by. */
    static final String SOURCE = "falldetection";

    private final Map<PersonNodeProvider, Connection> connections = new ConcurrentHashMap<>();
    private final AlertService alerts;
    private final DriverContext log;
    private final FallSettings settings;
    private final FallWords words;
    /** Where the person was last seen (room sensors); null: not watched (unit tests) */
    private final LastSeen seen;
    private final LastSeenWatch watch;

    @Activate
    public FallDetection(BundleContext context, FallDetectionConfig config,
            @Reference AlertService alerts) {
        this(new DriverContext(context, PID, "Fall Detection"), FallSettings.of(config), zone(config.timeZone()),
                alerts, new LastSeenWatch(context));
    }

    private FallDetection(DriverContext log, FallSettings settings, ZoneId zone, AlertService alerts,
            LastSeenWatch watch) {
        this(log, settings, zone, alerts, watch.lastSeen(), watch);
    }

    FallDetection(DriverContext log, FallSettings settings, ZoneId zone, AlertService alerts) {
        this(log, settings, zone, alerts, null, null);
    }

    FallDetection(DriverContext log, FallSettings settings, ZoneId zone, AlertService alerts, LastSeen seen,
            LastSeenWatch watch) {
        this.seen = seen;
        this.watch = watch;
        this.log = log;
        this.settings = settings;
        this.words = new FallWords(zone);
        this.alerts = alerts;
    }

    static ZoneId zone(String id) {
        if (id == null || id.isBlank()) {
            return ZoneId.systemDefault();
        }
        try {
            return ZoneId.of(id.strip());
        } catch (DateTimeException e) {
            return ZoneId.systemDefault();
        }
    }

    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC)
    void addNode(PersonNodeProvider node, Map<String, Object> properties) {
        Object address = properties.get(DeviceProperties.NODE_ADDRESS);
        String label = address == null ? node.deviceUid() : String.valueOf(address);
        connections.put(node, node.connect(new Listener(node, label, new FallDetector(settings))));
    }

    void removeNode(PersonNodeProvider node) {
        Connection c = connections.remove(node);
        if (c != null) {
            c.close();
        }
    }

    @Deactivate
    void deactivate() {
        connections.values().forEach(Connection::close);
        connections.clear();
        if (watch != null) {
            watch.close();
        }
        log.close();
    }

    /** One node's reports into its detector; a fall becomes an alert. */
    final class Listener implements PersonNodeListener {
        private final PersonNodeProvider node;
        private final String label;
        private final FallDetector detector;

        Listener(PersonNodeProvider node, String label, FallDetector detector) {
            this.node = node;
            this.label = label;
            this.detector = detector;
        }

        @Override
        public synchronized void movementSummarised(PersonNodeProvider source, MovementSummary summary) {
            detector.summary(summary).ifPresent(this::raise);
        }

        @Override
        public synchronized void burstReceived(PersonNodeProvider source, AccelerationBurst burst) {
            try {
                detector.burst(burst).ifPresent(this::raise);
            } catch (IllegalArgumentException e) {
                log.event(EventKind.PROBLEM, "a burst from node " + label + " was refused: "
                        + e.getMessage());
            }
        }

        private void raise(Fall f) {
            String person = person(node);
            String text = words.text(f, person, label, seen == null ? Optional.empty() : seen.last());
            alerts.raise(new AlertRequest(AlertKind.FALL, SOURCE + ":" + node.deviceUid(), "", "", f.detectedAt(),
                    words.subject(f, person), text));
            log.event(EventKind.DEVICE_EVENT, "FALL alert handed to the alert service: " + text);
        }
    }

    private static String person(PersonNodeProvider node) {
        try {
            Optional<String> p = node.person();
            return p.map(String::strip).orElse("");
        } catch (RuntimeException e) {
            return "";
        }
    }
}
