package org.tinysep.drivers.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** An in-memory framework: bundles by id with a location, a name and a running flag; records every call. */
final class FakeBundles implements Bundles {

    record FakeBundle(String location, String name, boolean running) {
    }

    final Map<Long, FakeBundle> installed = new LinkedHashMap<>();
    final List<String> calls = new ArrayList<>();
    private long nextId = 100;

    /** A bundle someone else installed (the launcher, Pax Exam, the shell). */
    long preinstalled(String location, String name, boolean running) {
        long id = nextId++;
        installed.put(id, new FakeBundle(location, name, running));
        return id;
    }

    @Override
    public long find(String symbolicName, String location) {
        return installed.entrySet().stream()
                .filter(e -> e.getValue().location().equals(location) || (!symbolicName.isEmpty()
                        && e.getValue().name().equals(symbolicName)))
                .mapToLong(Map.Entry::getKey).findFirst().orElse(-1);
    }

    @Override
    public long install(String location, int startLevel) throws Exception {
        calls.add("install " + location + " @" + startLevel);
        if (location.contains("broken")) {
            throw new Exception("invalid manifest");
        }
        String name = location.substring(location.lastIndexOf('/') + 1).replace(".jar", "");
        return preinstalled(location, name, false);
    }

    @Override
    public String symbolicName(long id) {
        FakeBundle b = installed.get(id);
        return b == null ? "" : b.name();
    }

    @Override
    public void start(long id) {
        calls.add("start " + symbolicName(id));
        installed.computeIfPresent(id, (k, b) -> new FakeBundle(b.location(), b.name(), true));
    }

    @Override
    public void stop(long id) {
        calls.add("stop " + symbolicName(id));
        installed.computeIfPresent(id, (k, b) -> new FakeBundle(b.location(), b.name(), false));
    }

    @Override
    public void uninstall(long id) {
        calls.add("uninstall " + symbolicName(id));
        installed.remove(id);
    }

    @Override
    public boolean isRunning(long id) {
        FakeBundle b = installed.get(id);
        return b != null && b.running();
    }

    @Override
    public String status(long id) {
        FakeBundle b = installed.get(id);
        return b == null ? "" : b.running() ? Status.ACTIVE : Status.STOPPED;
    }
}
