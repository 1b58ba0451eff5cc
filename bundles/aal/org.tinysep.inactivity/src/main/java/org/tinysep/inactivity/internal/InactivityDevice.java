package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.api.service.PersonWatch;
import org.tinysep.inactivity.internal.person.PersonAlertWords;
import org.tinysep.inactivity.internal.person.WearerSettings;
import org.tinysep.inactivity.internal.person.Wearers;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityRecognitionListener;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;
import org.tinysep.device.support.rooms.Placements;

/**
 * The one Inactivity Recognition device (thesis 4.4.4.1). Activity sources (movement, door, window) are vital;
 * Flat Occupancy, Mail Manager and House Information are optional. It watches the person: it is not removed when
 * its sources go, it says which rooms it can no longer see. Its parts: {@link ActivityFeed} (what happens,
 * into the detector and the wearers' watches), {@link StateAnnouncer} (what a state change leads to, the alert handed on),
 * {@link LoggedHistory} (the learner's history from the event log), {@link InactivityParameters}; the device
 * connects the providers, keeps the backup and is their {@link DeviceSide}.
 */
final class InactivityDevice extends WholeFlatDevice
        implements InactivityRecognitionProvider {

    /** While running, the state is saved this often (wall time), so after a crash it tells when it stopped. */
    private static final long HEARTBEAT_NANOS = 60_000_000_000L;

    private final Listeners<InactivityRecognitionListener> listeners;
    private final InactivityLogic logic;
    private final ActivityFactory activities;
    private final HelpCall help;
    private final AlertMail words;
    private volatile String occupancySource;
    private volatile long lastHeartbeat = System.nanoTime();
    private final RoomActivity rooms = new RoomActivity();
    private final LimitPolicy policy;
    private final LoggedHistory history;
    private final StateAnnouncer announcer;
    private final ActivityFeed feed;
    private final DeviceSide side;
    /** Each wearer of a person node, watched on their own (README "Activity per person"). */
    private volatile PersonWatches persons;

    InactivityDevice(DriverContext context, Placements directory, LimitTable limits, AlertMail words) {
        this(context, directory, limits, words, LimitPolicy.thesis(), null);
    }

    /**
     * @param policy  fixed (THESIS) or learned (LEARNED) limits
     * @param fromLog the LEARNED detector's entries from the event log's history waiting for their devices, or null
     */
    InactivityDevice(DriverContext context, Placements directory, LimitTable limits, AlertMail words,
            LimitPolicy policy, HistoryFromLog fromLog) {
        super(context, Uids.of(context.driverName(), "inactivity"), context.driverName(), "Inactivity recognition");
        this.listeners = new Listeners<>(uid());
        this.side = new DeviceSide(this::event, this::saveBackup, this::stateChanged, this::status,
                (s, at) -> listeners.fire(l -> l.inactivityStateChanged(this, s, at)));
        this.logic = new InactivityLogic(limits.defaultLimit(), context.now());
        this.policy = policy;
        this.help = new HelpCall(words);
        this.words = words;
        this.announcer = new StateAnnouncer(logic, help, words, () -> persons, side);
        this.feed = new ActivityFeed(logic, rooms, policy, words, () -> persons, announcer, side);
        this.activities = new ActivityFactory(directory, limits, policy, this::now, feed::activity);
        this.history = new LoggedHistory(fromLog, activities);
        watchPersons(WearerSettings.defaults(), java.time.ZoneId.systemDefault(), HelpCall::inFramework);
        limits.problems().forEach(p -> context.reporter().event(EventKind.PROBLEM, uid(), p));
        status(DeviceStatus.State.ONLINE, "");
        publish(this, InactivityRecognitionProvider.class);
    }

    void watch(MovementProvider p) {
        connect(p, MovementProvider.class, activities, true);
        if (p.location() == MovementLocation.INSIDE) {
            history.source(p.deviceUid());
        }
    }

    void watch(DoorProvider p) {
        connect(p, DoorProvider.class, activities, true);
        history.source(p.deviceUid());
    }

    void watch(WindowProvider p) {
        connect(p, WindowProvider.class, activities, true);
        history.source(p.deviceUid());
    }

    void watch(PresenceProvider p) {
        connect(p, PresenceProvider.class, activities, true);
        history.source(p.deviceUid());
    }

    /** Sets how wearers of person nodes are watched (before the backup is restored and any person node given). */
    void watchPersons(WearerSettings settings, java.time.ZoneId zone, HelpCall.AlertDesk desk) {
        PersonAlertWords w = new PersonAlertWords(zone);
        java.time.Duration limit;
        synchronized (logic) {
            limit = logic.defaultLimit();
        }
        persons = new PersonWatches(new Wearers(settings, w::time), w, limit, desk, help::mailer);
    }

    /** A person node: its movement is its wearer's activity (its wearer gets a watch of their own). */
    void use(PersonNodeProvider p) {
        connect(p, PersonNodeProvider.class, new PersonNodeListener() {
            @Override
            public void movementSummarised(PersonNodeProvider source, MovementSummary summary) {
                feed.personMoved(source, summary, now());
            }
        }, false);
    }

    /** @return the room type of a room House Information knows, else empty (for the learner's sleep rule) */
    String roomType(String roomUid) {
        return activities.typeOf(roomUid);
    }

    void use(FlatOccupancyProvider p) {
        occupancySource = p.deviceUid();
        connect(p, FlatOccupancyProvider.class, (src, occupancy, at) -> feed.occupancy(occupancy, at), false);
        feed.occupancy(p.occupancy(), p.since());
    }

    void use(MailManagerProvider p) {
        help.add(p);
        connect(p, MailManagerProvider.class, (src, status, at) -> { }, false);
        announcer.handOn();
    }

    void use(HouseInformationProvider p) {
        connect(p, HouseInformationProvider.class, (src, rooms, at) -> activities.rooms(rooms), false);
        activities.rooms(p.rooms());
    }

    /** A provider went away: forget what this device held of it (the driver closes the connection). */
    void forget(String providerUid) {
        help.remove(providerUid);
        persons.remove(providerUid);
        if (providerUid.equals(occupancySource)) {
            occupancySource = null;
            feed.occupancy(Occupancy.UNKNOWN, now());
        }
    }

    /** Advances the algorithm's clock; called every platform second by the driver. */
    void tick(Instant now) {
        feed.tick(now);
        history.resolve(side);
        long wall = System.nanoTime();
        if (wall - lastHeartbeat >= HEARTBEAT_NANOS) {
            lastHeartbeat = wall;
            saveBackup(); // its time tells, after a crash, until when this device was running
        }
    }

    /** It stays when its sensors go and says which rooms it can no longer see. */
    @Override
    protected boolean watchesThePerson() {
        return true;
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(InactivityRecognitionListener listener) {
        return listeners.add(listener);
    }

    @Override
    public InactivityState state() {
        synchronized (logic) {
            return logic.state();
        }
    }

    @Override
    public Optional<InactivityAlert> alert() {
        return announcer.alert();
    }

    @Override
    public List<PersonWatch> persons() {
        return persons.persons();
    }

    @Override
    protected List<Parameter> moreParameters() {
        return InactivityParameters.of(logic, policy, help, rooms, activities, persons);
    }

    @Override
    protected Map<String, String> backupState() {
        return InactivityBackup.state(logic, rooms, help, persons);
    }

    /** After a restart: the flat's watch and each wearer's come back ({@link InactivityBackup#restore}). */
    @Override
    protected void onRestore(ComponentBackup saved) {
        InactivityBackup.Restored r = InactivityBackup.restore(saved, now(), logic, rooms, help, words, persons);
        r.problems().forEach(p -> context.reporter().event(EventKind.PROBLEM, uid(), p));
        r.events().forEach(this::event);
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
