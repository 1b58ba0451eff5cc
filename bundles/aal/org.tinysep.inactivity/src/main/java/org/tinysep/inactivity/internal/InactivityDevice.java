package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Supplier;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.api.service.PersonWatch;
import org.tinysep.inactivity.internal.person.PersonAlertWords;
import org.tinysep.inactivity.internal.person.WearerSettings;
import org.tinysep.inactivity.internal.person.Wearers;
import org.tinysep.inactivity.internal.learn.Sighting;
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
 * its sources go, it says which rooms it can no longer see.
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
    private final HistoryFromLog fromLog;
    /** The activity sources connected so far (devices whose logged entries count as history). */
    private final Set<String> sources = ConcurrentHashMap.newKeySet();
    private volatile long lastResolve = System.nanoTime() - HEARTBEAT_NANOS;
    /** Each wearer of a person node, watched on their own (README, "Activity per person"). */
    private volatile PersonWatches persons;
    /** The flat's alert not handed on because wearers have their own watches (said once per alert). */
    private volatile Instant flatAlertLeftToPersons;

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
        this.logic = new InactivityLogic(limits.defaultLimit(), context.now());
        this.policy = policy;
        this.fromLog = fromLog;
        this.activities = new ActivityFactory(directory, limits, policy, this::now, this::activity);
        this.help = new HelpCall(words);
        this.words = words;
        watchPersons(WearerSettings.defaults(), java.time.ZoneId.systemDefault(), HelpCall::inFramework);
        limits.problems().forEach(p -> context.reporter().event(EventKind.PROBLEM, uid(), p));
        status(DeviceStatus.State.ONLINE, "");
        publish(this, InactivityRecognitionProvider.class);
    }

    void watch(MovementProvider p) {
        connect(p, MovementProvider.class, activities, true);
        if (p.location() == MovementLocation.INSIDE) {
            sources.add(p.deviceUid());
        }
    }

    void watch(DoorProvider p) {
        connect(p, DoorProvider.class, activities, true);
        sources.add(p.deviceUid());
    }

    void watch(WindowProvider p) {
        connect(p, WindowProvider.class, activities, true);
        sources.add(p.deviceUid());
    }

    void watch(PresenceProvider p) {
        connect(p, PresenceProvider.class, activities, true);
        sources.add(p.deviceUid());
    }

    /** Sets how wearers of person nodes are watched (before the backup is restored and any person node given). */
    void watchPersons(WearerSettings settings, java.time.ZoneId zone, HelpCall.AlertDesk desk) {
        PersonAlertWords w = new PersonAlertWords(zone);
        persons = new PersonWatches(new Wearers(settings, w::time), w, limitDefault(), desk, help::mailer);
    }

    private java.time.Duration limitDefault() {
        synchronized (logic) {
            return logic.defaultLimit();
        }
    }

    /** A person node: its movement is its wearer's activity (its wearer gets a watch of their own). */
    void use(PersonNodeProvider p) {
        connect(p, PersonNodeProvider.class, new PersonNodeListener() {
            @Override
            public void movementSummarised(PersonNodeProvider source, MovementSummary summary) {
                personMoved(source, summary);
            }
        }, false);
    }

    private void personMoved(PersonNodeProvider source, MovementSummary summary) {
        Instant now = now();
        PersonWatches.Moved m = persons.summary(source.deviceUid(), source.person(), summary, now);
        m.events().forEach(this::event);
        personSave(m.events()); // the wearer's watch (README "System backup and restarts")
        m.activity().ifPresent(a -> { // someone moved: the flat is active too
            Optional<InactivityState> change;
            synchronized (logic) {
                logic.rebase(now);
                change = logic.activity(a);
            }
            announce(change, a.at(), a::description);
        });
    }

    /** @return the room type of a room House Information knows, else empty (for the learner's sleep rule) */
    String roomType(String roomUid) {
        return activities.typeOf(roomUid);
    }

    /** Hands logged history of devices that are now sources to the learner (at most once a minute). */
    private void resolveHistory() {
        long wall = System.nanoTime();
        if (fromLog == null || wall - lastResolve < HEARTBEAT_NANOS || !fromLog.hasPending()) {
            return;
        }
        lastResolve = wall;
        int n = fromLog.resolve(raw -> {
            if (!sources.contains(raw.device())) {
                return Optional.empty();
            }
            ActivityFactory.Placed p = activities.placed(raw.device());
            return Optional.of(new Sighting(raw.at(), p.uid(), p.name(), p.type(), raw.inBed(), raw.seated()));
        });
        if (n > 0) {
            event("learning: " + n + " logged activities of connected sensors added to the history");
        }
    }

    void use(FlatOccupancyProvider p) {
        occupancySource = p.deviceUid();
        connect(p, FlatOccupancyProvider.class, (src, occupancy, at) -> occupancy(occupancy, at), false);
        occupancy(p.occupancy(), p.since());
    }

    void use(MailManagerProvider p) {
        help.add(p);
        connect(p, MailManagerProvider.class, (src, status, at) -> { }, false);
        mailPendingAlert();
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
            occupancy(Occupancy.UNKNOWN, now());
        }
    }

    private void activity(Activity a) {
        Optional<InactivityState> change;
        Optional<Instant> wentBack;
        Instant now = now();
        synchronized (logic) {
            wentBack = logic.rebase(now); // the platform's time, not the report's: a late report is no clock step
            change = logic.activity(a);
        }
        wentBack.ifPresent(from -> clockWentBack(from, now));
        rooms.seen(a);
        stateChanged(); // last activity per room, saved at most every 10 s (docs/backup.md)
        announce(change, a.at(), () -> a.description() + " in " + a.roomName()); // built on a change only
        List<String> said = persons.room(a, now);
        said.forEach(this::event);
        personSave(said);
    }

    /**
     * A wearer's watch changed: saved at once when it said something (a state change, a hand-over, worn or not
     * worn), else at most every 10 s like the flat's activity (docs/backup.md).
     */
    private void personSave(List<String> said) {
        if (said.isEmpty()) {
            stateChanged();
        } else {
            saveBackup();
        }
    }

    /** The clock went back: says so in plain words (the logic already counts the quiet time from now). */
    private void clockWentBack(Instant from, Instant now) {
        String room = lastRoom();
        event("clock went back from " + words.time(from) + " to " + words.time(now) + ": quiet time"
                + (room.isEmpty() ? "" : " in " + room) + " counted from now");
        saveBackup();
    }

    private String lastRoom() {
        synchronized (logic) {
            return logic.lastActivity().map(Activity::roomName).orElse("");
        }
    }

    private void occupancy(Occupancy occupancy, Instant at) {
        if (occupancy != Occupancy.UNKNOWN) {
            policy.occupancy(occupancy == Occupancy.UNOCCUPIED, at);
        }
        Optional<InactivityState> change;
        synchronized (logic) {
            change = logic.occupancy(occupancy, at);
        }
        announce(change, at, () -> "flat " + lower(occupancy));
        List<String> said = persons.occupancy(occupancy, at);
        said.forEach(this::event);
        if (!said.isEmpty()) {
            saveBackup();
        }
    }

    /** Advances the algorithm's clock; called every platform second by the driver. */
    void tick(Instant now) {
        Optional<InactivityState> change;
        Optional<Instant> wentBack;
        synchronized (logic) {
            wentBack = logic.rebase(now);
            change = logic.tick(now);
        }
        wentBack.ifPresent(from -> clockWentBack(from, now));
        announce(change, now, () -> "limit reached");
        List<String> said = persons.tick(now);
        said.forEach(this::event);
        if (!said.isEmpty()) {
            saveBackup(); // a wearer's alert raised or handed on: not handed on twice after a restart
        }
        resolveHistory();
        long wall = System.nanoTime();
        if (wall - lastHeartbeat >= HEARTBEAT_NANOS) {
            lastHeartbeat = wall;
            saveBackup(); // its time tells, after a crash, until when this device was running
        }
    }

    private void announce(Optional<InactivityState> change, Instant at, Supplier<String> reason) {
        change.ifPresent(s -> {
            String detail = s == InactivityState.ALERT ? alert().map(a -> help.subject(a) + words.why(a)).orElse("")
                    : "";
            event("inactivity " + lower(s) + " (" + reason.get() + ")" + (detail.isEmpty() ? "" : ": " + detail));
            listeners.fire(l -> l.inactivityStateChanged(this, s, at));
            saveBackup(); // whether (since when) the flat is watched survives a crash
            if (s == InactivityState.ALERT) {
                mailPendingAlert();
            } else {
                status(DeviceStatus.State.ONLINE, "");
            }
        });
    }

    /** Hands the current alert on once, as soon as the alert service or a Mail Manager is there. */
    private void mailPendingAlert() {
        Optional<InactivityAlert> a = alert();
        if (a.isEmpty()) {
            return;
        }
        List<String> wearers = persons.watched();
        if (!wearers.isEmpty()) { // each wearer's own watch calls for help for them (README "Activity per person")
            if (!a.get().raisedAt().equals(flatAlertLeftToPersons)) {
                flatAlertLeftToPersons = a.get().raisedAt();
                event("the flat's inactivity alert is not handed on: " + String.join(", ", wearers) + " wear"
                        + (wearers.size() == 1 ? "s a person node and is" : " person nodes and are") + " watched "
                        + "on their own, and that watch calls for help (it counts the room sensors when nobody "
                        + "else's node moves)");
            }
            return;
        }
        HelpCall.Outcome outcome = help.call(a.get());
        switch (outcome) {
            case HANDED_OVER, HANDED_TO_ALERT_SERVICE, RAISED_AGAIN -> {
                event(help.outcomeWords(a.get(), outcome == HelpCall.Outcome.RAISED_AGAIN));
                status(DeviceStatus.State.ONLINE, "");
                saveBackup(); // not handed over twice after a restart
            }
            case NO_MAIL_MANAGER -> status(DeviceStatus.State.ERROR, "alert raised but no Mail Manager to send it");
            case ALREADY_HANDED_OVER -> { }
        }
    }

    private static String lower(Enum<?> e) {
        return e.name().toLowerCase(Locale.ROOT).replace('_', ' ');
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
        synchronized (logic) {
            return logic.alert();
        }
    }

    @Override
    public List<PersonWatch> persons() {
        return persons.persons();
    }

    @Override
    protected List<Parameter> moreParameters() {
        synchronized (logic) {
            return List.of(
                    Parameter.readOnly("state", logic.state(), "current state"),
                    Parameter.readOnly("since", logic.since(), "when it was entered"),
                    Parameter.readOnly("deadline", logic.deadline().map(Instant::toString).orElse(""),
                            "when help is called if nothing happens"),
                    Parameter.readOnly("lastActivity", logic.lastActivity()
                            .map(a -> a.description() + " in " + a.roomName() + " at " + a.at()).orElse(""),
                            "the last activity seen"),
                    Parameter.readOnly("limitReason", logic.lastActivity().map(Activity::explanation).orElse(""),
                            "why the deadline is what it is (detector " + policy.name() + ")"),
                    Parameter.readOnly("alert", logic.alert().map(help::subject).orElse(""), "the raised alert"),
                    Parameter.readOnly("lastActivityPerRoom", rooms.describe(), "room uid = last activity there"),
                    Parameter.readOnly("knownRooms", activities.knownRooms(), "rooms known from House Information"),
                    Parameter.readOnly("persons", persons.describe(), "wearers of person nodes, each watched on "
                            + "their own"));
        }
    }

    @Override
    protected Map<String, String> backupState() {
        Map<String, String> state;
        synchronized (logic) {
            state = new java.util.LinkedHashMap<>(rooms.state(logic.lastActivity().orElse(null),
                    logic.watchingFrom().orElse(null), help.handedOverDue()));
        }
        state.putAll(persons.state()); // each wearer's watch (PersonBackup)
        return state;
    }

    /**
     * After a restart: the last activity, since when the flat was watched and the alert already handed over come
     * back, so the quiet time that began before keeps counting once Flat Occupancy (restored too) says OCCUPIED;
     * an alert that fell due meanwhile is raised by the first tick and says it is late. Times from the future are
     * counted from now. Each wearer's own watch comes back too ({@link PersonBackup}).
     */
    @Override
    protected void onRestore(ComponentBackup saved) {
        Restart.Report r = Restart.apply(saved, now(), logic, rooms, help, words);
        List<String> problems = new java.util.ArrayList<>(r.problems());
        List<String> events = new java.util.ArrayList<>(r.events());
        events.addAll(persons.restore(saved.state(), now(), problems)); // each wearer's watch
        problems.forEach(p -> context.reporter().event(EventKind.PROBLEM, uid(), p));
        events.forEach(this::event);
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
