package org.tinysep.runtime.internal.directory;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;

/** A hand-made {@link Device} following the API contract: writable and read-only parameters, one function. */
public final class FakeDevice implements Device {

    public final String uid;
    public final String type;
    public final String driverUid;
    public String name;
    public DeviceStatus status = DeviceStatus.online(Instant.parse("2026-01-01T00:00:00Z"));
    public final Map<String, Parameter> parameters = new LinkedHashMap<>();
    public final List<DeviceFunction> functions = new ArrayList<>();
    public final List<ConnectionInfo> connections = new ArrayList<>();
    public final List<String> invoked = new ArrayList<>();
    public RuntimeException failure; // thrown by every call when set

    public FakeDevice(String uid, String type, String driverUid, String name) {
        this.uid = uid;
        this.type = type;
        this.driverUid = driverUid;
        this.name = name;
    }

    public FakeDevice parameter(Parameter p) {
        parameters.put(p.key(), p);
        return this;
    }

    @Override
    public String uid() {
        return uid;
    }

    @Override
    public String type() {
        return type;
    }

    @Override
    public String driverUid() {
        return driverUid;
    }

    @Override
    public String name() {
        fail();
        return name;
    }

    @Override
    public DeviceStatus status() {
        fail();
        return status;
    }

    @Override
    public List<Parameter> parameters() {
        fail();
        return List.copyOf(parameters.values());
    }

    @Override
    public void setParameter(String key, String value) {
        fail();
        Parameter p = parameters.get(key);
        if (p == null) {
            throw new IllegalArgumentException("unknown parameter " + key);
        }
        if (!p.writable()) {
            throw new IllegalArgumentException(key + " is read-only");
        }
        if (key.equals("timeout") && !value.matches("\\d+")) {
            throw new IllegalArgumentException("timeout must be a whole number of seconds, not '" + value + "'");
        }
        if (key.equals("on") && parameters.containsKey("pending")) { // an actuator: the node's report will change the value
            parameters.put("pending", Parameter.readOnly("pending", value, "requested, not yet confirmed"));
            return;
        }
        parameters.put(key, Parameter.writable(key, value, p.description()));
    }

    @Override
    public List<DeviceFunction> functions() {
        fail();
        return List.copyOf(functions);
    }

    @Override
    public String invoke(String function) {
        fail();
        if (functions.stream().noneMatch(f -> f.name().equals(function))) {
            throw new IllegalArgumentException("no function " + function);
        }
        invoked.add(function);
        return "did " + function;
    }

    @Override
    public List<ConnectionInfo> connections() {
        fail();
        return List.copyOf(connections);
    }

    private void fail() {
        if (failure != null) {
            throw failure;
        }
    }
}
