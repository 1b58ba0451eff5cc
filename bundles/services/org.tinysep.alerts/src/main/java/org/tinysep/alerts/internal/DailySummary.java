package org.tinysep.alerts.internal;

import java.time.Instant;
import java.time.LocalDate;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.List;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Device;
import org.tinysep.device.support.lifecycle.ServiceUse;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.health.SensorHealthProvider;
import org.tinysep.api.device.DeviceStatus;

/**
 * The daily "TinySEP is running" mail to the Mail Manager's recipients at {@code summaryTime},
 * so that a missing summary is itself the signal. Sent once per day (the day is saved with the alerts); if the
 * platform was not running at that time, it goes out late at the next start the same day and says so. A fresh
 * installation started after today's time sends its first summary tomorrow.
 */
final class DailySummary implements AutoCloseable {

    private final AlertSettings settings;
    private final BundleContext context;
    private final ServiceTracker<SensorHealthProvider, SensorHealthProvider> health;
    private final SummaryText text;

    private final java.util.function.BiFunction<Instant, Instant, List<org.tinysep.api.log.EventEntry>> signals;

    /** @param signals the caregiver signals of the event log between two times (null: no log) */
    DailySummary(BundleContext context, AlertSettings settings, java.nio.file.Path stateFolder,
            java.util.function.BiFunction<Instant, Instant, List<org.tinysep.api.log.EventEntry>> signals) {
        this.signals = signals;
        this.settings = settings;
        this.context = context; // devices are read once a day, not held (holding them slows a stop with 10,000 devices)
        this.health = new ServiceTracker<>(context, SensorHealthProvider.class, null);
        this.health.open();
        this.text = new SummaryText(new AlertText(settings.zone()), stateFolder);
    }

    /** At activation: without a saved day, today's summary is due only if its time is still to come. */
    void start(AlertBook book, Instant now) {
        if (settings.summaryTime() == null || book.lastSummary() != null) {
            return;
        }
        ZonedDateTime local = now.atZone(settings.zone());
        book.lastSummary(local.toLocalTime().isBefore(settings.summaryTime()) ? local.toLocalDate().minusDays(1)
                : local.toLocalDate());
    }

    /** Sends today's summary once its time has come; the caller holds the alert service's lock. */
    void tick(AlertBook book, Instant now, Notifier notifier) {
        if (settings.summaryTime() == null) {
            return;
        }
        ZonedDateTime local = now.atZone(settings.zone());
        LocalDate today = local.toLocalDate();
        if (local.toLocalTime().isBefore(settings.summaryTime())
                || (book.lastSummary() != null && !book.lastSummary().isBefore(today))) {
            return;
        }
        List<Device> offline = offlineDevices();
        ZonedDateTime due = today.atTime(settings.summaryTime()).atZone(settings.zone());
        boolean late = local.isAfter(due.plusMinutes(5));
        List<org.tinysep.api.log.EventEntry> reduced = signals.apply(due.toInstant().minus(java.time.Duration
                .ofDays(1)), now);
        var mail = notifier.sendPlain(text.subject(today, book.open().size(), offline.size())
                + (reduced == null || reduced.isEmpty() ? "" : ", MONITORING REDUCED " + reduced.size() + " time(s)"),
                text.body(now, due.toInstant(), late, book.open(), offline, lowBatteries(), reduced));
        if (mail.isPresent()) {
            book.lastSummary(today); // saved: one summary per day, also across restarts
            notifier.events().accept("daily summary sent to the Mail Manager's recipients" + (late
                    ? " (late: TinySEP was not running at " + settings.summaryTime() + ")" : "") + ": "
                    + book.open().size() + " open alert(s), " + offline.size() + " device(s) offline or failing");
        }
    }

    /**
     * @return when {@link #tick} next has a summary to send: {@code now} while today's is due and not sent, else the
     *         next day's summary time; null without a summary time
     */
    static Instant nextDue(AlertSettings settings, LocalDate lastSent, Instant now) {
        if (settings.summaryTime() == null) {
            return null;
        }
        LocalDate day = now.atZone(settings.zone()).toLocalDate();
        if (lastSent != null && !lastSent.isBefore(day)) {
            day = day.plusDays(1); // today's was sent
        }
        Instant at = day.atTime(settings.summaryTime()).atZone(settings.zone()).toInstant();
        return at.isBefore(now) ? now : at;
    }

    @Override
    public void close() {
        health.close();
    }

    /** @return the devices OFFLINE or in ERROR now; each service is got for the check only */
    private List<Device> offlineDevices() {
        List<Device> out = new ArrayList<>();
        try {
            for (ServiceReference<Device> ref : context.getServiceReferences(Device.class, null)) {
                Device d = ServiceUse.take(context, ref); // no use left per device in the registry
                if (d != null) {
                    try {
                        DeviceStatus.State s = d.status().state();
                        if (s == DeviceStatus.State.OFFLINE || s == DeviceStatus.State.ERROR) {
                            out.add(d);
                        }
                    } catch (RuntimeException gone) { // a device going away: not listed
                    } finally {
                        ServiceUse.release(context, ref);
                    }
                }
            }
        } catch (InvalidSyntaxException | IllegalStateException e) { // no filter; or the bundle is stopping
        }
        return out;
    }

    /** @return Sensor Health's nodes with a low battery, or null when Sensor Health is not running */
    private List<SensorHealth> lowBatteries() {
        SensorHealthProvider h = health.getService();
        if (h == null) {
            return null;
        }
        try {
            return h.sensors().stream().filter(s -> s.node().batteryLow()).toList();
        } catch (RuntimeException e) { // Sensor Health going away: the summary still goes out
            return null;
        }
    }
}
