package org.tinysep.runtime.internal.directory;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;

/** A hand-made {@link Driver} that records which devices it was asked to remove. */
public final class FakeDriver implements Driver {

    public final String uid;
    public final String name;
    public final List<Device> devices = new ArrayList<>();
    public final List<Parameter> parameters = new ArrayList<>();
    public final List<String> removeCalls = new ArrayList<>();

    public FakeDriver(String uid, String name) {
        this.uid = uid;
        this.name = name;
    }

    @Override
    public String uid() {
        return uid;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public List<Device> devices() {
        return List.copyOf(devices);
    }

    @Override
    public List<Parameter> parameters() {
        return List.copyOf(parameters);
    }

    @Override
    public boolean removeDevice(String deviceUid) {
        removeCalls.add(deviceUid);
        return devices.removeIf(d -> d.uid().equals(deviceUid));
    }
}
