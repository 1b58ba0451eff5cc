package org.tinysep.sensorhealth.internal;

import java.time.Instant;
import java.util.Comparator;
import java.util.List;
import java.util.function.Function;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.health.SensorHealthListener;
import org.tinysep.api.health.SensorHealthProvider;
import org.tinysep.api.health.UnmonitoredRoom;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.device.support.health.HealthWords;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;
import org.tinysep.sensorhealth.internal.Notices.Notice;

/**
 * The one Sensor Health device: each platform second it reads every node's health, keeps the list of unmonitored
 * rooms (event log and listeners on each change) and sends the notices that are due, by mail through the Mail
 * Manager when one is installed, always in the event log.
 */
final class SensorHealthDevice extends WholeFlatDevice implements SensorHealthProvider {

    static final String TYPE = "SensorHealth";

    private final NodeIndex index;
    private final Function<String, String> roomName;
    private final NoticeWords words;
    private final Supplier<MailManagerProvider> mail;
    private final boolean mailNotices;
    private final long noticeAfterMinutes;
    private final Listeners<SensorHealthListener> listeners;
    private volatile List<UnmonitoredRoom> unmonitored = List.of();
    private volatile long sent;
    private volatile String lastNotice = "";
    /** What the status line last said (tick thread only): it is built again only when one of them changes. */
    private int shownAll = -1;
    private int shownOffline = -1;
    private List<UnmonitoredRoom> shownUnmonitored = List.of();

    SensorHealthDevice(DriverContext context, NodeIndex index, Function<String, String> roomName, NoticeWords words,
            Supplier<MailManagerProvider> mail, SensorHealthConfig config) {
        super(context, Uids.of(context.driverName(), "sensors"), TYPE, "Sensor health");
        this.index = index;
        this.roomName = roomName;
        this.words = words;
        this.mail = mail;
        this.mailNotices = config.mailNotices();
        this.noticeAfterMinutes = Math.max(0, config.noticeAfterMinutes());
        this.listeners = new Listeners<>(uid());
        publish(this, SensorHealthProvider.class);
    }

    /**
     * One platform tick: only the nodes whose state or place changed are looked at again ({@link NodeIndex}).
     *
     * @return when it is next due ({@link NodeIndex#nextDue}): every tick while nodes are known, null without any
     */
    Instant tick(Instant now) {
        update(now);
        return index.nextDue(now);
    }

    private void update(Instant now) {
        NodeIndex.Changes changes = index.tick(now);
        index.rooms().dropRemovedRooms(r -> context.rooms().house().isPresent() && context.rooms().room(r).isEmpty());
        List<UnmonitoredRoom> rooms = index.rooms().unmonitored();
        unmonitored = rooms.isEmpty() ? List.of() : rooms.stream().map(this::named)
                .sorted(Comparator.comparing(UnmonitoredRoom::roomName)).toList();
        rooms(changes.rooms(), now);
        if (!changes.notices().isEmpty()) {
            send(changes.notices());
        }
        int all = index.known();
        int offline = index.offline();
        List<UnmonitoredRoom> u = unmonitored;
        if (all == shownAll && offline == shownOffline && u.equals(shownUnmonitored)) {
            return; // the status line would say the same: not built again
        }
        shownAll = all;
        shownOffline = offline;
        shownUnmonitored = u;
        status(DeviceStatus.State.ONLINE, offline == 0 ? "all " + all + " sensors heard"
                : offline + " of " + all + " sensors offline" + (u.isEmpty() ? ""
                        : "; unmonitored: " + u.stream().map(UnmonitoredRoom::roomName)
                                .collect(Collectors.joining(", "))));
    }

    /** The room with its current name (the house may have renamed it since it became unmonitored). */
    private UnmonitoredRoom named(UnmonitoredRoom r) {
        String name = roomName.apply(r.roomUid());
        return name.equals(r.roomName()) ? r : new UnmonitoredRoom(r.roomUid(), name, r.since(), r.deviceUids());
    }

    private void rooms(RoomWatch.Changes changes, Instant at) {
        for (UnmonitoredRoom u : changes.unmonitored()) {
            UnmonitoredRoom r = named(u);
            context.reporter().event(EventKind.PROBLEM, uid(), "room " + r.roomName() + " is unmonitored: none "
                    + "of its sensors has been heard since " + HealthWords.time(r.since())
                    + "; inactivity there cannot be seen until one reports again");
            listeners.fire(l -> l.roomUnmonitored(this, r, at));
        }
        for (UnmonitoredRoom u : changes.sensorGone()) {
            event("room " + named(u).roomName() + " stays unmonitored: its sensor device was removed while none of its "
                    + "sensors was heard; it is monitored again only when a sensor placed there reports");
        }
        for (UnmonitoredRoom u : changes.monitoredAgain()) {
            UnmonitoredRoom r = named(u);
            event("room " + r.roomName() + " is monitored again: a sensor there reports again");
            listeners.fire(l -> l.roomMonitoredAgain(this, r.roomUid(), at));
        }
    }

    private void send(List<Notice> due) {
        String subject = words.subject(due);
        MailManagerProvider m = mailNotices ? mail.get() : null;
        if (m != null) {
            m.send(subject, words.body(due));
        }
        sent++;
        lastNotice = subject;
        event("notice: " + subject.substring(NoticeWords.PREFIX.length()) + (m != null
                ? " (mailed to the caregivers)" : mailNotices ? " (not mailed: no Mail Manager installed)"
                : " (not mailed: mailNotices=false)"));
    }

    @Override
    public List<SensorHealth> sensors() {
        return index.sensors();
    }

    @Override
    public List<UnmonitoredRoom> unmonitoredRooms() {
        return unmonitored;
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(SensorHealthListener listener) {
        return listeners.add(listener);
    }

    @Override
    protected List<Parameter> moreParameters() {
        List<SensorHealth> all = index.sensors();
        return List.of(
                Parameter.readOnly("sensors", all.size(), "nodes watched"),
                Parameter.readOnly("offline", list(all.stream().filter(s -> !s.node().online()).toList()),
                        "silent nodes, with their room"),
                Parameter.readOnly("unmonitoredRooms", unmonitored.stream().map(r -> r.roomName() + " since "
                        + HealthWords.time(r.since())).collect(Collectors.joining(", ")),
                        "rooms none of whose movement, door or window sensors is heard"),
                Parameter.readOnly("lowBatteries", list(all.stream().filter(s -> s.node().batteryLow()).toList()),
                        "nodes reporting a low battery"),
                Parameter.readOnly("noticeAfterMinutes", noticeAfterMinutes, "OFFLINE this long before a notice"),
                Parameter.readOnly("notices", sent, "notices sent"),
                Parameter.readOnly("lastNotice", lastNotice, "subject of the last notice"));
    }

    private static String list(List<SensorHealth> s) {
        return s.stream().map(h -> h.name() + (h.roomName() == null ? "" : " in " + h.roomName()))
                .collect(Collectors.joining(", "));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
