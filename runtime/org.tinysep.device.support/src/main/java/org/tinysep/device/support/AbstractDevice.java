package org.tinysep.device.support;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.device.Provider;
import org.tinysep.api.log.EventKind;

/**
 * Common part of every device: identity, name, status, consumed connections and the lifecycle of its services.
 * A driver constructs the device, then calls {@link #register()}; {@link #dispose()} removes it again.
 */
public abstract class AbstractDevice implements Device {

    protected final DriverContext context;
    private final String uid;
    private final String type;
    private final DeviceServices services = new DeviceServices();
    private final Consumptions consumptions = new Consumptions();
    private final RoomPlacement room;
    private final DeviceBackup backup = new DeviceBackup(this);
    private volatile String name;
    private volatile DeviceStatus status;

    protected AbstractDevice(DriverContext context, String uid, String type, String name) {
        this.context = Objects.requireNonNull(context, "context");
        this.uid = Objects.requireNonNull(uid, "uid");
        this.type = Objects.requireNonNull(type, "type");
        this.name = Objects.requireNonNull(name, "name");
        this.status = new DeviceStatus(DeviceStatus.State.UNKNOWN, "", context.now());
        services.property(DeviceProperties.DEVICE_UID, uid);
        services.property(DeviceProperties.DEVICE_TYPE, type);
        services.property(DeviceProperties.DRIVER_UID, context.driverUid());
        services.property(DeviceProperties.DRIVER_NAME, context.driverName());
        this.room = new RoomPlacement(uid, context, services::property, backup::save);
    }

    /**
     * @return whether the device has a {@code room} parameter (default true); services of the whole flat, like
     *         Flat Occupancy or House Information, override this to return false
     */
    protected boolean placeable() {
        return true;
    }

    /** @return the UID of the room the device is placed in, or null */
    protected final String roomUid() {
        return room.roomUid();
    }

    /** Declares a provider service to register with the device; call from the constructor. */
    protected final void publish(Object provider, Class<?>... interfaces) {
        services.publish(provider, interfaces);
    }

    /** Sets (or with null removes) a service property on all of this device's services. */
    protected final void serviceProperty(String key, Object value) {
        services.property(key, value);
    }

    /** Registers the device's services. Called by its driver once constructed. */
    final void register() {
        services.register(context.bundleContext(), this);
        onRegistered();
        backup.activate(); // after its connections: nothing delays them
    }

    /** Called once the device's services are registered: the place to connect to the providers it needs. */
    protected void onRegistered() {
    }

    /** Unregisters the services and closes every connection, both ways. Called by its driver. */
    final void dispose() {
        backup.save(); // the last state (e.g. last seen) before an orderly stop
        backup.deactivate();
        room.close();
        // inputs before services: once its inputs are closed, what arrives for this device waits for a replacement
        // (a bus device's Handover); had the services gone first, a payload arriving in between would reach this
        // device with no consumer left to tell (lost during a driver update)
        for (ConnectionInfo c : consumptions.infos()) {
            context.reporter().event(EventKind.DISCONNECTED, uid, "disconnected from " + c.interfaceName() + " of "
                    + c.providerDeviceUid());
        }
        consumptions.closeAll();
        services.unregister();
        onDispose();
    }

    /** Closes what the device itself holds, e.g. its listener lists. */
    protected void onDispose() {
    }

    /** Connects {@code listener} to {@code provider} and remembers the connection. */
    protected final <L> void connect(Provider<L> provider, Class<?> providerInterface, L listener, boolean vital) {
        consumptions.add(providerInterface.getSimpleName(), provider.deviceUid(), vital, provider.connect(listener));
        context.reporter().event(EventKind.CONNECTED, uid, "connected to " + providerInterface.getSimpleName()
                + " of " + provider.deviceUid() + (vital ? " (vital)" : " (optional)"));
    }

    /**
     * Drops every connection to the given provider device.
     *
     * @return whether the device still holds a vital connection afterwards
     */
    final boolean providerGone(String providerUid) {
        for (ConnectionInfo c : consumptions.infos()) {
            if (c.providerDeviceUid().equals(providerUid) && consumptions.remove(c.interfaceName(), providerUid)) {
                context.reporter().event(EventKind.DISCONNECTED, uid, "disconnected from " + c.interfaceName()
                        + " of " + providerUid + " (provider removed)");
            }
        }
        return consumptions.hasVital();
    }

    /** Records an observation in the event log, e.g. "door opened". */
    protected final void event(String message) {
        context.reporter().event(EventKind.DEVICE_EVENT, uid, message);
    }

    /** Changes the status; a change is recorded in the event log. */
    protected final void status(DeviceStatus.State state, String detail) {
        DeviceStatus old = status;
        if (old.state() == state && old.detail().equals(detail == null ? "" : detail)) {
            return;
        }
        status = new DeviceStatus(state, detail, context.now());
        context.reporter().event(EventKind.STATUS, uid, "status " + status);
    }

    @Override
    public final String uid() {
        return uid;
    }

    @Override
    public final String type() {
        return type;
    }

    @Override
    public final String driverUid() {
        return context.driverUid();
    }

    @Override
    public final String name() {
        return name;
    }

    @Override
    public final DeviceStatus status() {
        return status;
    }

    @Override
    public final List<ConnectionInfo> connections() {
        return consumptions.infos();
    }

    @Override
    public final List<Parameter> parameters() {
        List<Parameter> all = new ArrayList<>();
        all.add(Parameter.writable("name", name, "name shown to the user"));
        if (placeable()) {
            all.add(room.parameter());
        }
        all.addAll(moreParameters());
        return all;
    }

    /** @return parameters beyond {@code name} and {@code room}, in display order */
    protected List<Parameter> moreParameters() {
        return List.of();
    }

    @Override
    public final void setParameter(String key, String value) {
        if ("name".equals(key)) {
            if (value == null || value.isBlank()) {
                throw new IllegalArgumentException("name must not be blank");
            }
            name = value.strip();
            context.reporter().event(EventKind.DEVICE_EVENT, uid, "renamed to \"" + name + "\"");
        } else if (RoomPlacement.KEY.equals(key) && placeable()) {
            room.set(value);
        } else {
            applyParameter(key, value);
        }
        backup.save(); // no waiting here: the shell waits (BackupStore.flush) before it acknowledges
    }

    // ---- system backup (thesis 3.7, docs/backup.md)

    /** @return this device's backup as of now: name, room, kept writable parameters, node, state */
    public final ComponentBackup backup() {
        return backup.snapshot(placeable() ? room.roomUid() : null, parameters(),
                services.property(DeviceProperties.NODE_ADDRESS), services.property(DeviceProperties.NODE_TYPE),
                lastSeen(), backupState());
    }

    /** Applies a saved backup before the device registers; called by its driver. */
    final void restore(ComponentBackup saved) {
        if (!saved.name().isBlank()) {
            name = saved.name();
        }
        DeviceBackup.restore(this, saved, room, placeable());
        onRestore(saved);
    }

    /** @return whether a writable parameter is a setting kept in the backup (default all; commands are not) */
    protected boolean backedUp(String key) {
        return true;
    }

    /** @return when the device's node was last heard from, for the backup; null when not applicable */
    protected Instant lastSeen() {
        return null;
    }

    /** @return runtime state to keep across restarts (e.g. last activity per room); default none */
    protected Map<String, String> backupState() {
        return Map.of();
    }

    /** Takes runtime state back from a saved backup, before the device registers; default nothing. */
    protected void onRestore(ComponentBackup saved) {
    }

    /** Saves the backup soon (no disk I/O on the caller's thread), e.g. after the device changed a setting. */
    protected final void saveBackup() {
        backup.save();
    }

    /** Runtime state changed (e.g. a packet arrived): saved at most once per 10 s; cheap on the packet path. */
    protected final void stateChanged() {
        backup.stateChanged();
    }

    /** Applies a parameter other than {@code name} and {@code room}; the default knows none. */
    protected void applyParameter(String key, String value) {
        throw unknownParameter(key);
    }

    protected final IllegalArgumentException unknownParameter(String key) {
        List<String> writable = parameters().stream().filter(Parameter::writable).map(Parameter::key).toList();
        return new IllegalArgumentException("unknown or read-only parameter '" + key + "' of " + type
                + "; writable: " + String.join(", ", writable));
    }

    @Override
    public List<DeviceFunction> functions() {
        return List.of();
    }

    @Override
    public String invoke(String function) {
        throw new IllegalArgumentException(type + " has no function '" + function + "'");
    }

    /** @return the platform's current time */
    protected final Instant now() {
        return context.now();
    }

    @Override
    public String toString() {
        return type + " " + uid;
    }
}
