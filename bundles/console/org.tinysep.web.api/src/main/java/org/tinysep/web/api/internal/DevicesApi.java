package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;
import org.tinysep.web.api.internal.PlatformView.DeviceRef;

/** {@code /api/devices} and {@code /api/drivers}: the devices and drivers as JSON, setting parameters, invoking functions. */
public final class DevicesApi {

    private final PlatformView platform;

    public DevicesApi(PlatformView platform) {
        this.platform = platform;
    }

    /** GET /api/devices */
    public List<Object> list() {
        Map<String, String> names = platform.names();
        Map<String, String> rooms = roomNames();
        List<Object> out = new ArrayList<>();
        for (DeviceRef d : platform.devices()) {
            out.add(device(d, names, rooms));
        }
        return out;
    }

    /** GET /api/devices/{uid} */
    public Map<String, Object> one(String uid) {
        DeviceRef d = find(uid);
        return device(d, platform.names(), roomNames());
    }

    /** PUT /api/devices/{uid}/parameters/{key} with {"value": "..."}: 400 with the device's message when refused */
    public Map<String, Object> setParameter(String uid, String key, String value) {
        DeviceRef d = find(uid);
        if (value == null) {
            throw ApiException.badRequest("the body must be {\"value\": \"...\"}");
        }
        try {
            d.device().setParameter(key, value);
        } catch (IllegalArgumentException e) {
            throw ApiException.badRequest(key + ": " + e.getMessage());
        }
        Map<String, Object> out = new LinkedHashMap<>(one(uid));
        boolean saved = platform.withService(BackupStore.class, s -> s.flush(Duration.ofSeconds(10))).orElse(true);
        out.put("saved", saved);
        return out;
    }

    /** POST /api/devices/{uid}/functions/{name} */
    public Map<String, Object> invoke(String uid, String function) {
        DeviceRef d = find(uid);
        try {
            Map<String, Object> out = new LinkedHashMap<>();
            out.put("result", d.device().invoke(function));
            return out;
        } catch (IllegalArgumentException e) {
            throw ApiException.badRequest(function + ": " + e.getMessage());
        }
    }

    /** GET /api/drivers */
    public List<Object> drivers() {
        List<Object> out = new ArrayList<>();
        for (Driver d : platform.drivers()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("uid", Safely.get(d::uid, ""));
            m.put("name", Safely.get(d::name, ""));
            m.put("devices", Safely.get(() -> d.devices().stream().map(Device::uid).toList(), List.of()));
            m.put("parameters", parameters(Safely.get(d::parameters, List.of())));
            out.add(m);
        }
        return out;
    }

    private DeviceRef find(String uid) {
        return platform.device(uid).orElseThrow(() -> ApiException.notFound("no device with UID " + uid));
    }

    private Map<String, String> roomNames() {
        Map<String, String> out = new LinkedHashMap<>();
        platform.withService(HouseInformationProvider.class, HouseInformationProvider::rooms)
                .ifPresent(rooms -> rooms.forEach((Room r) -> out.put(r.uid(), r.name())));
        return out;
    }

    private static Map<String, Object> device(DeviceRef ref, Map<String, String> names, Map<String, String> rooms) {
        Device d = ref.device();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("uid", ref.uid());
        m.put("name", Safely.get(d::name, ref.uid()));
        m.put("type", Safely.get(d::type, ""));
        m.put("driverUid", Safely.get(d::driverUid, ""));
        m.put("driverName", ref.driverName());
        DeviceStatus s = Safely.get(d::status, null);
        Map<String, Object> status = new LinkedHashMap<>();
        status.put("state", s == null ? "UNKNOWN" : s.state().name());
        status.put("detail", s == null ? "the device did not answer" : s.detail());
        status.put("since", s == null ? null : s.since());
        m.put("status", status);
        if (ref.room().isEmpty()) {
            m.put("room", null);
        } else {
            Map<String, Object> room = new LinkedHashMap<>(); // keys in a fixed order, like every answer
            room.put("uid", ref.room());
            room.put("name", rooms.getOrDefault(ref.room(), ref.room()));
            m.put("room", room);
        }
        m.put("nodeAddress", ref.nodeAddress());
        m.put("nodeTypes", ref.nodeTypes());
        m.put("provides", ref.provides());
        m.put("parameters", parameters(Safely.get(d::parameters, List.of())));
        List<Object> functions = new ArrayList<>();
        for (DeviceFunction f : Safely.get(d::functions, List.<DeviceFunction>of())) {
            Map<String, Object> fm = new LinkedHashMap<>();
            fm.put("name", f.name());
            fm.put("description", f.description());
            functions.add(fm);
        }
        m.put("functions", functions);
        List<Object> connections = new ArrayList<>();
        for (ConnectionInfo c : Safely.get(d::connections, List.<ConnectionInfo>of())) {
            Map<String, Object> cm = new LinkedHashMap<>();
            cm.put("interface", c.interfaceName());
            cm.put("providerUid", c.providerDeviceUid());
            cm.put("providerName", names.getOrDefault(c.providerDeviceUid(), ""));
            cm.put("vital", c.vital());
            connections.add(cm);
        }
        m.put("connections", connections);
        return m;
    }

    private static List<Object> parameters(List<Parameter> parameters) {
        List<Object> out = new ArrayList<>();
        for (Parameter p : parameters) {
            Map<String, Object> pm = new LinkedHashMap<>();
            pm.put("key", p.key());
            pm.put("value", p.value());
            pm.put("writable", p.writable());
            pm.put("description", p.description());
            pm.put("options", ParameterOptions.of(p));
            out.add(pm);
        }
        return out;
    }
}
