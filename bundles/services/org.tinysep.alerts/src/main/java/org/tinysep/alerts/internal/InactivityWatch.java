package org.tinysep.alerts.internal;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.InactivityRecognitionListener;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;

/**
 * Ends inactivity alerts when their cause ends: Inactivity Recognition leaving {@code ALERT} means the person is
 * active again (→ {@code WATCHING}) or the flat became unoccupied (→ {@code NOT_WATCHING}: Flat Occupancy decided
 * from door and movement reports that someone left). The alert service then sends the all clear. A device going
 * away never leaves {@code ALERT}: Inactivity Recognition stays in it when Flat Occupancy or a
 * sensor goes, and an Inactivity Recognition that goes (its bundle stops) clears nothing here. Raising is
 * Inactivity Recognition's help call (it hands each alert over once, also across restarts, with the words of its
 * mail).
 */
@Component(immediate = true)
public final class InactivityWatch {

    /** The source name Inactivity Recognition raises its alerts with. */
    public static final String SOURCE = "inactivity";
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss 'UTC'")
            .withZone(ZoneOffset.UTC);

    private final Map<InactivityRecognitionProvider, Connection> connections = new ConcurrentHashMap<>();
    private final Map<InactivityRecognitionProvider, InactivityState> last = new ConcurrentHashMap<>();

    @Reference
    private AlertService alerts;

    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC)
    void bindInactivity(InactivityRecognitionProvider p) {
        last.put(p, p.state());
        connections.put(p, p.connect(new InactivityRecognitionListener() {
            @Override
            public void inactivityStateChanged(InactivityRecognitionProvider source, InactivityState state,
                    Instant at) {
                changed(source, state, at);
            }
        }));
    }

    void unbindInactivity(InactivityRecognitionProvider p) {
        Connection c = connections.remove(p);
        if (c != null) {
            c.close();
        }
        last.remove(p);
    }

    void changed(InactivityRecognitionProvider p, InactivityState state, Instant at) {
        InactivityState before = last.put(p, state);
        if (before != InactivityState.ALERT || state == InactivityState.ALERT) {
            return;
        }
        alerts.clear(SOURCE, state == InactivityState.WATCHING
                ? "the person is active again (Inactivity Recognition saw activity at " + TIME.format(at) + ")"
                : "the flat became unoccupied at " + TIME.format(at) + " (someone left), so it is not watched");
    }
}
