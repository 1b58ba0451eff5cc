package org.tinysep.device.support.lifecycle;

import java.time.Instant;
import java.util.List;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.PacketLog;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.device.support.logs.Reporter;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.time.PlatformClock;

/**
 * What a driver shares with its devices: the bundle context to register services with, the driver's identity,
 * the log reporter, the platform clock, the rooms and the backup store.
 */
public final class DriverContext implements AutoCloseable {

    private final BundleContext bundleContext;
    private final String driverUid;
    private final String driverName;
    private final Reporter reporter;
    private final PlatformClock clock;
    private final RoomDirectory rooms;
    private final Backups backups;
    private final ConsumerIndex consumers = new ConsumerIndex();
    /** The platform services followed for this context in a framework; null with explicit parts. */
    private PlatformServices platform;

    /**
     * The context of a driver running in a framework: logs, clock, rooms and backups follow the services, all
     * through one service listener ({@link PlatformServices}).
     */
    public DriverContext(BundleContext bundleContext, String driverUid, String driverName) {
        this(bundleContext, driverUid, driverName, Followed.of(bundleContext));
    }

    private DriverContext(BundleContext bundleContext, String driverUid, String driverName, Followed f) {
        this(bundleContext, driverUid, driverName, f.reporter(), f.clock(), f.rooms(), f.backups());
        this.platform = f.services();
    }

    /** The parts of a framework's context over one {@link PlatformServices}. */
    private record Followed(PlatformServices services, Reporter reporter, PlatformClock clock, RoomDirectory rooms,
            Backups backups) {

        static Followed of(BundleContext bc) {
            PlatformServices[] s = new PlatformServices[1];
            RoomDirectory rooms = RoomDirectory.over(() -> s[0].get(HouseInformationProvider.class));
            s[0] = new PlatformServices(bc, List.of(EventLog.class, PacketLog.class, TimeControllerProvider.class,
                    HouseInformationProvider.class, BackupStore.class),
                    o -> o instanceof HouseInformationProvider h ? rooms.listenTo(h) : null);
            PlatformServices p = s[0];
            return new Followed(p, new Reporter(() -> p.get(EventLog.class), () -> p.get(PacketLog.class)),
                    new PlatformClock(() -> {
                        TimeControllerProvider t = p.get(TimeControllerProvider.class);
                        return t == null ? Instant.now() : t.now();
                    }), rooms, Backups.over(() -> p.get(BackupStore.class)));
        }
    }

    /**
     * A context with explicit parts. With a null bundle context, devices can be built and exercised but not
     * registered: the seam unit tests use.
     */
    public DriverContext(BundleContext bundleContext, String driverUid, String driverName, Reporter reporter,
            PlatformClock clock) {
        this(bundleContext, driverUid, driverName, reporter, clock, RoomDirectory.none());
    }

    /** A context with explicit parts including the rooms (e.g. {@link RoomDirectory#of} a fake house). */
    public DriverContext(BundleContext bundleContext, String driverUid, String driverName, Reporter reporter,
            PlatformClock clock, RoomDirectory rooms) {
        this(bundleContext, driverUid, driverName, reporter, clock, rooms, Backups.none());
    }

    /** A context with explicit parts including the backup store (e.g. {@link Backups#of} an in-memory one). */
    public DriverContext(BundleContext bundleContext, String driverUid, String driverName, Reporter reporter,
            PlatformClock clock, RoomDirectory rooms, Backups backups) {
        this.rooms = rooms;
        this.backups = backups;
        this.bundleContext = bundleContext;
        this.driverUid = driverUid;
        this.driverName = driverName;
        this.reporter = reporter;
        this.clock = clock;
    }

    public BundleContext bundleContext() {
        if (bundleContext == null) {
            throw new IllegalStateException(driverName + " runs without a framework; nothing can be registered");
        }
        return bundleContext;
    }

    /**
     * @return whether the driver's bundle is stopping (or its context is no longer valid): its trackers then report
     *         every provider as removed, which is not the providers going away. Never true without a framework.
     */
    public boolean stopping() {
        return stopping(bundleContext);
    }

    /** @return whether the whole framework is stopping (the platform shuts down); never true without one */
    public boolean frameworkStopping() {
        if (bundleContext == null) {
            return false;
        }
        try {
            org.osgi.framework.Bundle system = bundleContext.getBundle(0);
            return system == null || (system.getState() & (Bundle.STOPPING | Bundle.RESOLVED)) != 0;
        } catch (IllegalStateException e) {
            return true;
        }
    }

    static boolean stopping(BundleContext bundleContext) {
        if (bundleContext == null) {
            return false;
        }
        try {
            return (bundleContext.getBundle().getState() & (Bundle.STOPPING | Bundle.RESOLVED | Bundle.UNINSTALLED))
                    != 0;
        } catch (IllegalStateException e) {
            return true; // the context was invalidated: the bundle has stopped
        }
    }

    public String driverUid() {
        return driverUid;
    }

    public String driverName() {
        return driverName;
    }

    public Reporter reporter() {
        return reporter;
    }

    /** @return the rooms devices can be placed in */
    public RoomDirectory rooms() {
        return rooms;
    }

    /** @return the device manager's backup store, when installed (thesis 3.7) */
    public Backups backups() {
        return backups;
    }

    /** @return which of the driver's devices are connected to which provider device */
    ConsumerIndex consumers() {
        return consumers;
    }

    public Instant now() {
        return clock.now();
    }

    /** Records an event-log entry originating from the driver. */
    public void event(EventKind kind, String message) {
        reporter.event(kind, driverUid, message);
    }

    @Override
    public void close() {
        rooms.close();
        backups.close();
        clock.close();
        reporter.close();
        if (platform != null) {
            platform.close();
        }
    }
}
