package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.ZoneId;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.SleepRule;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.inactivity.internal.person.WearerSettings;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.device.support.lifecycle.AbstractDriver;
import org.tinysep.device.support.lifecycle.SingleDeviceWiring;
import org.tinysep.device.support.rooms.TrackedPlacements;
import org.tinysep.device.support.rooms.UnmonitoredRooms;
import org.tinysep.device.support.time.PlatformTicker;

/**
 * Inactivity Recognition driver: creates its single device when the first activity source (Movement, Door or
 * Window) appears and connects it to every later one; Flat Occupancy, Mail Manager and House Information are
 * connected whenever present. The device watches the person: left without sources it stays (a deliberate
 * deviation from thesis 3.3, docs/architecture.md) and says which rooms it can no longer see.
 */
@Component(service = {}, immediate = true, configurationPid = InactivityDriver.PID)
@Designate(ocd = InactivityConfig.class)
public final class InactivityDriver extends AbstractDriver {

    static final String PID = "org.tinysep.inactivity";
    static final String NAME = "InactivityRecognition";
    private static final Logger LOG = LoggerFactory.getLogger(InactivityDriver.class);

    private SingleDeviceWiring<InactivityDevice> wiring;
    private LimitTable limits;
    private AlertMail words;
    private TrackedPlacements directory;
    private PlatformTicker ticker;
    private LimitPolicy policy;
    private HistoryLearner learner;
    private HistoryFromLog fromLog;
    private LearnedMemory memory;
    private ScheduledExecutorService loader;
    private UnmonitoredRooms unmonitored;
    private WearerSettings wearers;
    private ZoneId zone;

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile EventLog eventLog;

    public InactivityDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, InactivityConfig config) {
        limits = LimitTable.parse(config.defaultLimitMinutes(), config.typeLimits(), config.roomLimits());
        zone = zone(config.timeZone());
        start(bundleContext);
        wearers = wearers(config);
        unmonitored = new UnmonitoredRooms(bundleContext);
        words = new AlertMail(zone, unmonitored::now);
        policy = policy(config, zone);
        directory = new TrackedPlacements(bundleContext);
        wiring = new SingleDeviceWiring<>(this, InactivityDevice.class, this::newDevice, InactivityDevice::forget);
        wiring.optional(bundleContext, FlatOccupancyProvider.class, InactivityDevice::use);
        wiring.optional(bundleContext, MailManagerProvider.class, InactivityDevice::use);
        wiring.optional(bundleContext, HouseInformationProvider.class, InactivityDevice::use);
        wiring.optional(bundleContext, PersonNodeProvider.class, InactivityDevice::use);
        wiring.source(bundleContext, MovementProvider.class, (d, p) -> d.watch(p));
        wiring.source(bundleContext, DoorProvider.class, (d, p) -> d.watch(p));
        wiring.source(bundleContext, WindowProvider.class, (d, p) -> d.watch(p));
        wiring.source(bundleContext, PresenceProvider.class, (d, p) -> d.watch(p));
        ticker = new PlatformTicker(bundleContext, "inactivity", now -> wiring.current().forEach(d -> d.tick(now)));
        if (fromLog != null) {
            int days = learner.settings().historyDays();
            java.nio.file.Path folder = org.tinysep.device.support.files.StateFolder.resolveOrDataArea(null, bundleContext,
                    "inactivity");
            memory = folder == null ? null : new LearnedMemory(folder.resolve("learned-history.txt"));
            loader = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "inactivity-history"));
            loader.execute(() -> loadHistory(days));
            loader.scheduleWithFixedDelay(this::saveMemory, SAVE_MINUTES, SAVE_MINUTES, TimeUnit.MINUTES);
        }
    }

    /** THESIS: fixed limits. LEARNED: a learner fed from the event log's history and live activity. */
    private LimitPolicy policy(InactivityConfig config, ZoneId zone) {
        Detector d = config.detector() == null ? Detector.LEARNED : config.detector();
        if (d == Detector.THESIS) {
            return LimitPolicy.thesis();
        }
        LearningSettings defaults = LearningSettings.defaults();
        LearningSettings settings;
        SleepRule sleep;
        try {
            settings = new LearningSettings(config.learnMinDays(), Math.max(config.learnMinDays(),
                    config.learnHistoryDays()), defaults.margin(), defaults.pad(),
                    Duration.ofMinutes(config.learnFloorMinutes()), defaults.ceiling(), defaults.halfWindow(),
                    config.learnMinPeriodsToShorten(), config.residents());
            sleep = new SleepRule(config.nightStartHour(), config.nightEndHour(), zone);
        } catch (IllegalArgumentException e) {
            LOG.warn("learning configuration not usable ({}); using the defaults", e.getMessage());
            context().event(EventKind.PROBLEM, "learning configuration not usable (" + e.getMessage()
                    + "); using the defaults");
            settings = defaults;
            sleep = new SleepRule(21, 7, zone);
        }
        learner = new HistoryLearner(zone, sleep, settings);
        fromLog = new HistoryFromLog(learner);
        return LimitPolicy.learned(new LearnedLimits(learner));
    }

    /** The learner's own memory is saved this often (and when the driver stops). */
    static final long SAVE_MINUTES = 10;

    private void saveMemory() {
        if (memory == null) {
            return;
        }
        try {
            fromLog.save(memory, context().now());
        } catch (java.io.IOException | RuntimeException e) {
            LOG.warn("Could not save what the learned detector remembers in {}: {}", memory.file(), e.toString());
        }
    }

    private void loadHistory(int days) {
        EventLog log = eventLog;
        try {
            String said = fromLog.load(log, context().now(), days, memory);
            LOG.info("{}", said);
            context().event(EventKind.DEVICE_EVENT, said);
        } catch (RuntimeException e) {
            LOG.warn("event log history not read ({}); learning starts from live activity only", e.toString());
            context().event(EventKind.PROBLEM, "event log history not read (" + e.getMessage()
                    + "); learning starts from live activity only");
        }
    }

    @Deactivate
    void deactivate() {
        if (loader != null) {
            loader.shutdownNow();
            saveMemory(); // nothing when the history was not loaded yet
        }
        ticker.close();
        wiring.close();
        stop();
        directory.close();
        unmonitored.close();
    }

    /** @return the single device (not yet registered), its room types known to the learner */
    private InactivityDevice newDevice() {
        InactivityDevice d = new InactivityDevice(context(), directory, limits, words, policy, fromLog);
        d.watchPersons(wearers, zone, HelpCall::inFramework);
        if (learner != null) {
            learner.roomTypes(d::roomType);
        }
        return d;
    }

    /** The person-node settings (README "Activity per person"); the defaults when they are not usable. */
    private WearerSettings wearers(InactivityConfig config) {
        try {
            return new WearerSettings(config.personMovingAboveMg(),
                    Duration.ofSeconds(config.personMovingWithinSeconds()),
                    Duration.ofMinutes(config.personNotWornMinutes()));
        } catch (IllegalArgumentException e) {
            LOG.warn("person node settings not usable ({}); using the defaults", e.getMessage());
            context().event(EventKind.PROBLEM, "person node settings not usable (" + e.getMessage()
                    + "); using the defaults: movement above 30 mg, moving within 5 s, not worn after 120 min");
            return WearerSettings.defaults();
        }
    }

    private ZoneId zone(String id) {
        if (id == null || id.isBlank()) {
            return ZoneId.systemDefault();
        }
        try {
            return ZoneId.of(id.strip());
        } catch (RuntimeException e) {
            LOG.warn("timeZone '{}' is not a time zone ({}); using {}", id, e.getMessage(), ZoneId.systemDefault());
            return ZoneId.systemDefault();
        }
    }
}
