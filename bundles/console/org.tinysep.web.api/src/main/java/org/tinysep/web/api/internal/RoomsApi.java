package org.tinysep.web.api.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;

/** {@code /api/rooms}: House Information's rooms; add, rename/retype, link/unlink neighbours, remove (503 while House Information is not running). */
public final class RoomsApi {

    private final PlatformView platform;

    public RoomsApi(PlatformView platform) {
        this.platform = platform;
    }

    /** GET /api/rooms */
    public List<Object> list() {
        return house(h -> {
            List<Object> out = new ArrayList<>();
            h.rooms().forEach(r -> out.add(json(r)));
            return out;
        });
    }

    /** POST /api/rooms {"name","type"} */
    public Map<String, Object> add(Map<String, String> body) {
        return house(h -> json(h.addRoom(required(body, "name"), required(body, "type"))));
    }

    /** PUT /api/rooms/{uid} {"name","type"} */
    public Map<String, Object> update(String uid, Map<String, String> body) {
        return house(h -> {
            Room old = h.room(uid).orElseThrow(() -> ApiException.notFound("no room with UID " + uid));
            return json(h.updateRoom(uid, body.getOrDefault("name", old.name()), body.getOrDefault("type", old.type())));
        });
    }

    /** DELETE /api/rooms/{uid} */
    public Map<String, Object> remove(String uid) {
        return house(h -> {
            if (!h.removeRoom(uid)) {
                throw ApiException.notFound("no room with UID " + uid);
            }
            return Map.of("removed", uid);
        });
    }

    /** PUT /api/rooms/{uid}/neighbours/{other} (linked both ways) or DELETE (unlinked); @return the room */
    public Map<String, Object> link(String uid, String other, boolean linked) {
        return house(h -> {
            h.room(uid).orElseThrow(() -> ApiException.notFound("no room with UID " + uid));
            h.room(other).orElseThrow(() -> ApiException.notFound("no room with UID " + other + " to link to"));
            if (uid.equals(other)) {
                throw ApiException.badRequest("a room cannot be its own neighbour");
            }
            if (linked) {
                h.link(uid, other);
            } else {
                h.unlink(uid, other);
            }
            return json(h.room(uid).orElseThrow(() -> ApiException.notFound("no room with UID " + uid)));
        });
    }

    private <R> R house(Function<HouseInformationProvider, R> use) {
        try {
            return platform.withService(HouseInformationProvider.class, use)
                    .orElseThrow(() -> new ApiException(503, "House Information is not running"));
        } catch (IllegalArgumentException e) {
            throw ApiException.badRequest(e.getMessage());
        }
    }

    private static String required(Map<String, String> body, String key) {
        String v = body.get(key);
        if (v == null || v.isBlank()) {
            throw ApiException.badRequest(key + " is required");
        }
        return v.strip();
    }

    static Map<String, Object> json(Room r) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("uid", r.uid());
        m.put("name", r.name());
        m.put("type", r.type());
        m.put("neighbours", List.copyOf(new java.util.TreeSet<>(r.neighbours())));
        return m;
    }
}
