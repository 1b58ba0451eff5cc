package org.tinysep.runtime.internal;

import java.time.Duration;
import java.util.function.Supplier;
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

/**
 * The {@code tinysep} Gogo commands. Each returns its output as one String (no trailing newline), so it prints in
 * the shell and can be read through {@code CommandProcessor}. Errors are thrown as {@link IllegalArgumentException}
 * or {@link IllegalStateException} with a one-line message; Gogo prints them as one line, never a stack trace.
 * {@code set} clashes with {@code gogo:set}: type {@code tinysep:set}. The log commands are in
 * {@link HistoryCommands}.
 */
@Component(service = ShellCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=drivers",
    "osgi.command.function=devices",
    "osgi.command.function=remove",
    "osgi.command.function=set",
    "osgi.command.function=invoke"
})
public final class ShellCommands {

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
    public String drivers() {
        return run("drivers", () -> Listings.drivers(operations.drivers()));
    }

    /** {@code devices}: one block per device. */
    public String devices() {
        return run("devices", () -> DeviceBlocks.render(operations.devices()));
    }

    /** {@code remove <uid>}: a device (uid or unique prefix), else a driver (uid or name). */
    public String remove(String uid) {
        return run("remove", () -> operations.remove(uid));
    }

    /** {@code set <uid> <key> <value>}: changes one device parameter. */
    public String set(String uid, String key, String value) {
        return run("set", () -> operations.setParameter(uid, key, value) + durable());
    }

    /** {@code invoke <uid> <function>}: runs one device function. */
    public String invoke(String uid, String function) {
        return run("invoke", () -> operations.invoke(uid, function));
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
