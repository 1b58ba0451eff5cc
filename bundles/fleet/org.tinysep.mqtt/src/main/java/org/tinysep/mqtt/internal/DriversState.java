package org.tinysep.mqtt.internal;

import org.tinysep.device.support.lifecycle.Safely;
import static org.tinysep.json.JsonWriter.object;
import static org.tinysep.json.JsonWriter.writePlain;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.drivers.ApplicationEntry;
import org.tinysep.api.drivers.DriversListService;

/**
 * The drivers list on the broker: {@code P/F/drivers}, retained, from {@link DriversListService} (bundle
 * {@code org.tinysep.drivers}). The service has no change signal, so the list is read at every poll; the outbox
 * publishes it only when it differs from what is already published (and again after each reconnection).
 */
final class DriversState implements AutoCloseable {

    static final String RUNNING = "ACTIVE";

    private final Topics topics;
    private final Supplier<DriversListService> service;
    private final Runnable close;

    DriversState(Topics topics, Supplier<DriversListService> service, Runnable close) {
        this.topics = topics;
        this.service = service;
        this.close = close;
    }

    /** @return the drivers list of the service registered in {@code context}, as it comes and goes */
    static DriversState tracking(BundleContext context, Topics topics) {
        ServiceTracker<DriversListService, DriversListService> tracker =
                new ServiceTracker<>(context, DriversListService.class, null);
        tracker.open();
        return new DriversState(topics, tracker::getService, tracker::close);
    }

    /** @return the retained message with the list and a sentence saying what runs and what does not */
    Message message() {
        DriversListService s = service.get();
        List<ApplicationEntry> apps = s == null ? null : Safely.get(s::applications, null);
        if (apps == null) {
            String why = s == null ? "the drivers list is not known: its bundle (org.tinysep.drivers) is not running"
                    : "the drivers list did not answer; it is read again in a moment";
            return Message.state(topics.drivers(), writePlain(object("applications", List.of(), "explanation", why)));
        }
        List<Map<String, Object>> list = new ArrayList<>();
        List<String> notRunning = new ArrayList<>();
        for (ApplicationEntry a : apps) {
            list.add(object("application", a.application(), "symbolicName", a.symbolicName(),
                    "location", a.location(), "enabled", a.enabled(), "status", a.status()));
            if (!a.status().equals(RUNNING)) {
                notRunning.add(a.application() + " (" + (a.status().isEmpty() ? "no status yet" : a.status()) + ")");
            }
        }
        int running = apps.size() - notRunning.size();
        String words = apps.size() + (apps.size() == 1 ? " application" : " applications") + " in the drivers list, "
                + running + " running" + (notRunning.isEmpty() ? "" : "; not running: " + String.join(", ", notRunning));
        return Message.state(topics.drivers(), writePlain(object("applications", list, "running", running,
                "explanation", words)));
    }

    @Override
    public void close() {
        close.run();
    }
}
