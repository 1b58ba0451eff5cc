package org.tinysep.mqtt.internal;

import org.tinysep.device.support.lifecycle.Safely;
import static org.tinysep.json.JsonWriter.object;
import static org.tinysep.json.JsonWriter.writePlain;

import java.time.Instant;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;

/** The flat-wide retained messages: occupancy, platform heartbeat, daily summary, one state per alert kind. */
final class FlatState implements AutoCloseable {

    private final Topics topics;
    private final Tracked<FlatOccupancyProvider> occupancy;
    private final Supplier<Instant> clock;
    private final String version;
    private final Instant startedAt;
    private final int heartbeatSeconds;

    FlatState(BundleContext context, Topics topics, Supplier<Instant> clock, int heartbeatSeconds) {
        this.topics = topics;
        this.clock = clock;
        this.heartbeatSeconds = heartbeatSeconds;
        this.occupancy = new Tracked<>(context, FlatOccupancyProvider.class);
        this.version = context.getBundle().getVersion().toString();
        this.startedAt = clock.get();
    }

    void poll(Consumer<Message> out, AlertService alerts, Alerts words) {
        for (Tracked.Entry<FlatOccupancyProvider> e : occupancy.all().values()) {
            FlatOccupancyProvider p = e.service();
            Occupancy o = Safely.get(p::occupancy, Occupancy.UNKNOWN);
            Instant since = Safely.get(p::since, null);
            out.accept(Message.state(topics.occupancy(), writePlain(object("state", o.name(), "since", since,
                    "explanation", switch (o) {
                        case OCCUPIED -> "someone is at home" + (since == null ? "" : " (since " + since + ")");
                        case UNOCCUPIED -> "nobody is at home" + (since == null ? "" : " (since " + since + ")");
                        case UNKNOWN -> "not known yet whether someone is at home";
                    }))));
            break; // one flat, one Flat Occupancy
        }
        List<Alert> open = alerts == null ? List.of() : Safely.get(alerts::open, List.<Alert>of());
        for (AlertKind k : AlertKind.values()) {
            out.accept(words.kindState(k, open));
        }
    }

    Message platform() {
        return Message.state(topics.platform(), writePlain(object("flat", topics.flatId(), "version", version,
                "startedAt", startedAt, "heartbeatAt", clock.get(), "heartbeatSeconds", heartbeatSeconds,
                "explanation", "TinySEP of flat " + topics.flatId() + " is running; it says so every "
                        + heartbeatSeconds + " s")));
    }

    Message summary(AlertService alerts, int devices, int devicesOffline) {
        List<Alert> open = alerts == null ? List.of() : Safely.get(alerts::open, List.<Alert>of());
        Instant now = clock.get();
        String text = "TinySEP is running (" + now.toString().substring(0, 10) + "): "
                + (alerts == null ? "no alert service runs" : open.isEmpty() ? "no open alert"
                        : open.size() + " open alert(s)")
                + ", " + (devicesOffline == 0 ? "all " + devices + " devices online"
                        : devicesOffline + " of " + devices + " devices offline");
        return Message.state(topics.summary(), writePlain(object("at", now, "text", text,
                "openAlerts", open.size())));
    }

    @Override
    public void close() {
        occupancy.close();
    }
}
