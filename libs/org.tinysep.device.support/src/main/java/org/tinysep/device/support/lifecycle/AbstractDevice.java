package org.tinysep.device.support.lifecycle;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.device.Provider;
import org.tinysep.api.log.EventKind;

/**
 * Common part of every device. A driver constructs the device, then calls {@link #register()};
 * {@link #dispose()} removes it again. The hooks come in sections, one per concern, each done by a small
 * package-private part (see the README's "which part do I read"):
 * <ul>
 * <li>identity, services and connections: {@link DeviceRegistration};</li>
 * <li>parameters ({@code name}, {@code room}, the device's own): {@link DeviceParameters};</li>
 * <li>the system backup (thesis 3.7): {@link DeviceBackup};</li>
 * <li>status and events: {@link DeviceStatusHolder}.</li>
 * </ul>
 */
public abstract class AbstractDevice implements Device {

    protected final DriverContext context;
    private final String uid;
    private final String type;
    private final DeviceStatusHolder status;
    private final DeviceRegistration registration;
    private final DeviceBackup backup = new DeviceBackup(this);
    private final DeviceParameters parameters;
    private final LostSources lost = new LostSources();
    private final NodeFollow follow = new NodeFollow();

    protected AbstractDevice(DriverContext context, String uid, String type, String name) {
        this.context = Objects.requireNonNull(context, "context");
        this.uid = Objects.requireNonNull(uid, "uid");
        this.type = Objects.requireNonNull(type, "type");
        Objects.requireNonNull(name, "name");
        this.status = new DeviceStatusHolder(context, uid);
        this.registration = new DeviceRegistration(context, uid, type);
        this.parameters = new DeviceParameters(this, name, registration::property, backup::save);
    }

    // ---- identity, services and connections (DeviceRegistration)

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

    /** Declares a provider service to register with the device; call from the constructor. */
    protected final void publish(Object provider, Class<?>... interfaces) {
        registration.publish(provider, interfaces);
    }

    /** Sets (or with null removes) a service property on all of this device's services. */
    protected final void serviceProperty(String key, Object value) {
        registration.property(key, value);
    }

    /** Registers the device's services. Called by its driver once constructed. */
    final void register() {
        registration.register(this);
        onRegistered();
        backup.activate(); // after its connections: nothing delays them
    }

    /** Called once the device's services are registered: the place to connect to the providers it needs. */
    protected void onRegistered() {
    }

    /** Connects {@code listener} to {@code provider} and remembers the connection. */
    protected final <L> void connect(Provider<L> provider, Class<?> providerInterface, L listener, boolean vital) {
        registration.connect(provider, providerInterface, listener, vital);
        follow.connected(provider);
        LostSources.Lost back = lost.back(provider.deviceUid());
        if (back != null) {
            context.reporter().event(EventKind.DEVICE_EVENT, uid, LostSources.backWords(back));
        }
    }

    /**
     * @return whether this device watches the person (Inactivity Recognition, Flat Occupancy):
     *         it is then never removed because its sources went (a deliberate deviation from thesis 3.3: it keeps
     *         running, with no source left too), it reports each vital source lost as a {@code Monitoring reduced: }
     *         PROBLEM naming the sensor and its room, and lists them in its {@code roomsNotSeen} parameter until
     *         they are back. It still goes with its own driver. Default false: thesis behaviour.
     */
    protected boolean watchesThePerson() {
        return false;
    }

    @Override
    public final List<ConnectionInfo> connections() {
        return registration.connections();
    }

    /**
     * Drops every connection to the given provider device.
     *
     * @return whether the device still holds a vital connection afterwards
     */
    final boolean providerGone(String providerUid) {
        follow.gone(providerUid);
        return registration.providerGone(providerUid);
    }

    /**
     * Drops every connection to the given provider device, as its driver does when the provider went.
     *
     * @return whether the device stays: it still holds a vital connection, or it {@link #watchesThePerson()}
     */
    final boolean loseProvider(String providerUid) {
        boolean hadVital = registration.connectionsTo(providerUid).stream().anyMatch(ConnectionInfo::vital);
        Object provider = registration.provider(providerUid);
        follow.gone(providerUid);
        boolean stillVital = registration.providerGone(providerUid);
        if (!watchesThePerson()) {
            return stillVital;
        }
        if (hadVital && !context.frameworkStopping()) { // the whole platform stopping takes no sensor away
            LostSources.Lost l = LostSources.of(providerUid, provider, context.rooms(), now());
            lost.add(l);
            context.reporter().event(EventKind.PROBLEM, uid, LostSources.problem(name(), l, stillVital));
        }
        return true;
    }

    /** @return the rooms (sensors) this watching device can no longer see, in words; "" when none */
    final String roomsNotSeen() {
        return lost.describe();
    }

    /** Unregisters the services and closes every connection, both ways (inputs first). Called by its driver. */
    final void dispose() {
        backup.save(); // the last state (e.g. last seen) before an orderly stop
        backup.deactivate();
        parameters.close();
        registration.unregister();
        follow.clear();
        onDispose();
    }

    /** Closes what the device itself holds, e.g. its listener lists. */
    protected void onDispose() {
    }

    // ---- parameters (DeviceParameters)

    @Override
    public final String name() {
        return parameters.name();
    }

    /**
     * @return whether the device has a {@code room} parameter (default true); services of the whole flat, like
     *         Flat Occupancy or House Information, extend {@link WholeFlatDevice} instead
     */
    protected boolean placeable() {
        return true;
    }

    /** @return the UID of the room the device is placed in, or null */
    protected final String roomUid() {
        return parameters.roomUid();
    }

    @Override
    public final List<Parameter> parameters() {
        return parameters.list();
    }

    /** @return parameters beyond {@code name} and {@code room}, in display order */
    protected List<Parameter> moreParameters() {
        return List.of();
    }

    @Override
    public final void setParameter(String key, String value) {
        parameters.set(key, value);
        backup.save(); // no waiting here: the shell waits (BackupStore.flush) before it acknowledges
    }

    /** Applies a parameter other than {@code name} and {@code room}; the default knows none. */
    protected void applyParameter(String key, String value) {
        throw unknownParameter(key);
    }

    protected final IllegalArgumentException unknownParameter(String key) {
        return parameters.unknown(key);
    }

    // ---- system backup (thesis 3.7, docs/backup.md; DeviceBackup)

    /** @return this device's backup as of now: name, room, kept writable parameters, node, state */
    public final ComponentBackup backup() {
        return backup.snapshot(parameters, registration);
    }

    /** Applies a saved backup before the device registers; called by its driver. */
    final void restore(ComponentBackup saved) {
        backup.restore(saved, parameters);
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

    /** Tests: the device's side of the backup (its throttle's clock). */
    final DeviceBackup backupSide() {
        return backup;
    }

    /**
     * Runtime state changed (e.g. a packet arrived): looked at most once per 10 s, saved when it changes what a
     * restart needs (the last seen time alone: at most once per 60 s); cheap on the packet path.
     */
    protected final void stateChanged() {
        backup.stateChanged();
    }

    // ---- status, events, functions (DeviceStatusHolder)

    /**
     * @return the device's own status; but OFFLINE, with the reason, while the bus device of its node is OFFLINE
     *         ({@link NodeFollow}: no STATUS entry of its own for that)
     */
    @Override
    public final DeviceStatus status() {
        return follow.apply(status.get());
    }

    /** Changes the status; a change is recorded in the event log. */
    protected final void status(DeviceStatus.State state, String detail) {
        status.set(state, detail);
    }

    /** Records an observation in the event log, e.g. "door opened". */
    protected final void event(String message) {
        context.reporter().event(EventKind.DEVICE_EVENT, uid, message);
    }

    /** @return the platform's current time */
    protected final Instant now() {
        return context.now();
    }

    @Override
    public List<DeviceFunction> functions() {
        return List.of();
    }

    @Override
    public String invoke(String function) {
        throw new IllegalArgumentException(type + " has no function '" + function + "'");
    }

    @Override
    public String toString() {
        return type + " " + uid;
    }
}
