package org.tinysep.runtime.internal.shell;

import java.time.Duration;
import java.util.function.Supplier;
import org.apache.felix.service.command.Descriptor;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.device.support.lifecycle.Safely;
import org.tinysep.runtime.internal.directory.Inventory;

/**
 * The {@code tinysep} Gogo commands. Each returns its output as one String (no trailing newline), so it prints in
 * the shell and can be read through {@code CommandProcessor}. Errors are thrown as {@link IllegalArgumentException}
 * or {@link IllegalStateException} with a one-line message; Gogo prints them as one line, never a stack trace.
 * {@code set} clashes with {@code gogo:set}: type {@code tinysep:set}. The log commands are in
 * {@link HistoryCommands}.
 */
// name: the component name (and PID) it had before the runtime was split into packages
@Component(name = "org.tinysep.runtime.internal.ShellCommands",
        service = ShellCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=drivers",
    "osgi.command.function=devices",
    "osgi.command.function=remove",
    "osgi.command.function=set",
    "osgi.command.function=invoke"
})
public final class ShellCommands {

    static final String DEVICE = "a device's UID, its first characters (4 or more) or its name";
    static final String FILTER = "a UID or its first characters, a node address (e.g. 1.4), a driver name, or"
            + " part of a device name";
    private static final Logger LOG = LoggerFactory.getLogger(ShellCommands.class);

    private final Operations operations;
    /** The system backup (docs/backup.md): {@code set} is acknowledged once the change is on disk. */
    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC)
    volatile BackupStore backupStore;

    @Activate
    public ShellCommands(BundleContext context, @Reference(name = "inventory") Inventory inventory) {
        this(new Operations(inventory, id -> stop(context, id), context.getBundle().getBundleId()));
    }

    ShellCommands(Operations operations) {
        this.operations = operations;
    }

    /** {@code drivers}: one table row per driver. */
    @Descriptor("lists the drivers: UID, name, bundle, device count and figures (e.g. a bus radio's port)")
    public String drivers() {
        return run("drivers", () -> Listings.drivers(operations.drivers()));
    }

    /** {@code devices}: one block per device. */
    @Descriptor("lists every device: status, interfaces, connections, node, parameters, functions")
    public String devices() {
        return run("devices", () -> DeviceBlocks.render(operations.devices()));
    }

    /** {@code devices <filter>}: the blocks of the devices the filter names ({@link DeviceFilter}). */
    @Descriptor("lists the devices a filter names")
    public String devices(@Descriptor(FILTER) String filter) {
        return run("devices", () -> DeviceBlocks.render(operations.devices(filter)));
    }

    /** {@code remove <uid>}: a device (uid or unique prefix), else a driver (uid or name). */
    @Descriptor("removes a device, or a driver with all its devices (stops its bundle; 'start <id>' brings it back)")
    public String remove(@Descriptor(DEVICE + ", or a driver's UID or name") String uid) {
        return run("remove", () -> operations.remove(uid));
    }

    /** {@code set <uid> <key> <value>}: changes one device parameter. */
    @Descriptor("changes a device parameter, e.g. tinysep:set 1a2b room Kitchen; an actuator's change is pending"
            + " until the node confirms it")
    public String set(@Descriptor(DEVICE) String uid,
            @Descriptor("the parameter key (tinysep:devices shows them)") String key,
            @Descriptor("the new value") String value) {
        return run("set", () -> operations.setParameter(uid, key, value) + durable());
    }

    /** {@code invoke <uid> <function>}: runs one device function. */
    @Descriptor("runs a device function (tinysep:devices shows a device's functions)")
    public String invoke(@Descriptor(DEVICE) String uid, @Descriptor("the function's name") String function) {
        return run("invoke", () -> operations.invoke(uid, function));
    }

    /** {@code devices} with more than one argument: the usage, not Gogo's "Cannot coerce". */
    @Descriptor("with more than one argument: prints the usage")
    public String devices(@Descriptor("anything else") String... wrong) {
        throw Usage.of("devices [filter]", wrong);
    }

    /** {@code remove}, {@code set} or {@code invoke} with the wrong number of arguments: the usage. */
    @Descriptor("with a wrong number of arguments: prints the usage")
    public String remove(@Descriptor("anything else") String... wrong) {
        throw Usage.of("remove <uid or driver>", wrong);
    }

    @Descriptor("with a wrong number of arguments: prints the usage")
    public String set(@Descriptor("anything else") String... wrong) {
        throw Usage.of("set <uid> <key> <value>", wrong);
    }

    @Descriptor("with a wrong number of arguments: prints the usage")
    public String invoke(@Descriptor("anything else") String... wrong) {
        throw Usage.of("invoke <uid> <function>", wrong);
    }

    /** Waits until the change is in the system backup; @return "" when it is, else a note for the user. */
    private String durable() {
        BackupStore store = backupStore;
        return store == null || store.flush(Duration.ofSeconds(10)) ? ""
                : " (not yet saved in the system backup: the disk did not answer within 10 s)";
    }

    static String run(String command, Supplier<String> body) {
        try {
            return body.get();
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw e;
        } catch (RuntimeException e) {
            LOG.warn("tinysep:{} failed", command, e);
            throw new IllegalStateException(command + " failed: " + Safely.describe(e));
        }
    }

    private static String stop(BundleContext context, long bundleId) throws Exception {
        Bundle bundle = context.getBundle(bundleId);
        if (bundle == null) {
            throw new IllegalStateException("bundle " + bundleId + " is no longer installed");
        }
        bundle.stop(); // persistent: it stays stopped across restarts until started again
        return bundle.getSymbolicName();
    }
}
