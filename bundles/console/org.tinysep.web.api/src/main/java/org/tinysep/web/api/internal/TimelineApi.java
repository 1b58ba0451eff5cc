package org.tinysep.web.api.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;

/**
 * {@code GET /api/caregiver/timeline?days=1|7}: per room, how much activity there was in each slot of the last 24 h
 * (48 slots of 30 min) or 7 days (84 slots of 2 h), counted from the event log's history like the last activity of
 * {@link CaregiverApi}: movement, door and window reports of the sensors now placed in the room. Slots end at
 * "now" rounded up to the slot size.
 */
final class TimelineApi {

    static final int MAX_ENTRIES = 100_000;

    private final PlatformView platform;

    TimelineApi(PlatformView platform) {
        this.platform = platform;
    }

    Map<String, Object> timeline(EventLog log, Instant now, Map<String, String[]> params) {
        String[] d = params.get("days");
        String days = d == null || d.length == 0 ? "1" : d[0].strip();
        Duration slot;
        int slots;
        switch (days) {
            case "1" -> {
                slot = Duration.ofMinutes(30);
                slots = 48;
            }
            case "7" -> {
                slot = Duration.ofHours(2);
                slots = 84;
            }
            default -> throw ApiException.badRequest("days must be 1 or 7, not '" + Strings.shorten(days, 20) + "'");
        }
        long slotSeconds = slot.toSeconds();
        Instant to = Instant.ofEpochSecond(Math.floorDiv(now.getEpochSecond() + slotSeconds - 1, slotSeconds) * slotSeconds);
        Instant from = to.minus(slot.multipliedBy(slots));
        Map<String, String> sensorRoom = CaregiverApi.sensorRooms(platform);
        Map<String, int[]> counts = new HashMap<>();
        boolean complete = true;
        if (!sensorRoom.isEmpty()) {
            LogHistory<EventEntry> h = log.query(new LogQuery(from, to, sensorRoom.keySet(), Set.of("DEVICE_EVENT"), MAX_ENTRIES));
            complete = h.matched() <= h.entries().size();
            for (EventEntry e : h.entries()) {
                String room = sensorRoom.get(e.origin());
                if (room != null && CaregiverApi.isActivity(e.message())) {
                    int i = (int) (Duration.between(from, e.time()).toSeconds() / slotSeconds);
                    if (i >= 0 && i < slots) {
                        counts.computeIfAbsent(room, r -> new int[slots])[i]++;
                    }
                }
            }
        }
        List<Object> rooms = new ArrayList<>();
        for (Room r : platform.withService(HouseInformationProvider.class, HouseInformationProvider::rooms).orElse(List.of())) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("uid", r.uid());
            m.put("name", r.name());
            m.put("type", r.type());
            int[] c = counts.getOrDefault(r.uid(), new int[slots]);
            List<Integer> list = new ArrayList<>(slots);
            for (int v : c) {
                list.add(v);
            }
            m.put("counts", list);
            rooms.add(m);
        }
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("from", from);
        out.put("to", to.truncatedTo(ChronoUnit.SECONDS));
        out.put("slotMinutes", slot.toMinutes());
        out.put("complete", complete);
        out.put("rooms", rooms);
        out.put("now", now);
        return out;
    }
}
