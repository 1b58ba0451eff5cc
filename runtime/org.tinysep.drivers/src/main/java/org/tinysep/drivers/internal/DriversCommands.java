package org.tinysep.drivers.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.apache.felix.service.command.Descriptor;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;

/**
 * {@code tinysep:drivers [reload | enable <bsn> | disable <bsn> | use <bsn> <file>]}. Ranked above the device
 * manager's older
 * {@code tinysep:drivers} (a table of Driver services), whose content it includes below the list: every driver with
 * its application, device count and figures.
 */
@Component(service = DriversCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=drivers",
    "service.ranking:Integer=10"
})
public final class DriversCommands {

    static final String USAGE = "usage: tinysep:drivers [reload | enable <bsn> | disable <bsn> | use <bsn> <file>]"
            + " (help tinysep:drivers explains them)";

    private final BundleContext context;
    private final DriversList list;

    @Activate
    public DriversCommands(BundleContext context, @Reference DriversList list) {
        this.context = context;
        this.list = list;
    }

    /**
     * {@code drivers}: the list (each application with its status), then every Driver service with its application,
     * device count and figures (what the device manager's own {@code drivers} listing showed).
     */
    @Descriptor("the drivers list (var/drivers.xml: each application, enabled, status), then every driver with its"
            + " application, device count and figures")
    public String drivers() {
        List<DriverEntry> entries = list.entries();
        TextTable apps = new TextTable("APPLICATION", "ENABLED", "STATUS", "FILE");
        entries.forEach(e -> apps.row(e.key(), e.enabled() ? "yes" : "no", e.status(), e.location()));
        Set<String> listed = new HashSet<>();
        entries.forEach(e -> listed.add(e.symbolicName()));
        TextTable drivers = new TextTable("DRIVER", "APPLICATION", "DEVICES", "PARAMETERS");
        for (ServiceReference<Driver> ref : driverReferences()) {
            Driver d = context.getService(ref);
            Bundle b = ref.getBundle();
            if (d == null || b == null) {
                continue;
            }
            try {
                String bsn = String.valueOf(b.getSymbolicName());
                drivers.row(d.name(), listed.contains(bsn) ? bsn : bsn + " (not in the list)",
                        Integer.toString(d.devices().size()), parameters(d));
            } catch (RuntimeException e) {
                drivers.row(String.valueOf(ref.getProperty(DeviceProperties.DRIVER_NAME)), "-", "?", "error: " + e);
            } finally {
                context.ungetService(ref);
            }
        }
        return "Drivers list " + list.path() + " (" + entries.size() + " applications)\n" + apps.render()
                + "\n\n" + drivers.render();
    }

    /** {@code drivers reload} (or {@code list}). */
    @Descriptor("applies an edited drivers.xml: installs new entries, stops disabled ones, uninstalls removed ones")
    public String drivers(@Descriptor("reload (or list: the same as tinysep:drivers)") String action) {
        return switch (action.toLowerCase(Locale.ROOT)) {
            case "reload" -> {
                List<String> changes = list.reload();
                yield changes.isEmpty() ? "Drivers list reloaded: nothing to change" : "Drivers list reloaded:\n  "
                        + String.join("\n  ", changes);
            }
            case "list" -> drivers();
            case "enable", "disable" -> throw usage(action.toLowerCase(Locale.ROOT) + " needs the application's bundle symbolic name");
            case "use" -> throw usage("use needs the application's bundle symbolic name and the jar");
            default -> throw usage("unknown action '" + action + "'");
        };
    }

    /** {@code drivers enable|disable <bsn>}. */
    @Descriptor("switches one application on or off, in the drivers list too (it stays so across restarts)")
    public String drivers(@Descriptor("enable or disable") String action,
            @Descriptor("the application's bundle symbolic name, e.g. org.tinysep.followmelight") String bsn) {
        boolean enable = switch (action.toLowerCase(Locale.ROOT)) {
            case "enable" -> true;
            case "disable" -> false;
            case "use" -> throw usage("use needs the application's bundle symbolic name and the jar");
            default -> throw usage("unknown action '" + action + "'");
        };
        return String.join("\n", list.setEnabled(bsn, enable));
    }

    /** {@code drivers use <bsn> <file>}: the application is loaded from that file from the next start on. */
    @Descriptor("loads an application from another jar from the next start on (e.g. an update uploaded in the web"
            + " console); the running bundle is not touched")
    public String drivers(@Descriptor("use") String action,
            @Descriptor("the application's bundle symbolic name") String bsn,
            @Descriptor("the jar: a path (relative to tinysep.home) or a file: URL") String file) {
        if (!action.toLowerCase(Locale.ROOT).equals("use")) {
            throw usage("unknown action '" + action + "'");
        }
        return list.use(bsn, file);
    }

    /** {@code drivers} with more arguments than any form takes: the usage. */
    @Descriptor("with too many arguments: prints the usage")
    public String drivers(@Descriptor("anything else") String... wrong) {
        throw usage("wrong number of arguments (" + wrong.length + ")");
    }

    /** @return the error for wrong arguments: what is wrong, then the usage line */
    static IllegalArgumentException usage(String what) {
        return new IllegalArgumentException(what + "; " + USAGE);
    }

    private List<ServiceReference<Driver>> driverReferences() {
        try {
            List<ServiceReference<Driver>> refs = new ArrayList<>(context.getServiceReferences(Driver.class, null));
            refs.sort(Comparator.comparing(r -> String.valueOf(r.getProperty(DeviceProperties.DRIVER_NAME))));
            return refs;
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    private static String parameters(Driver d) {
        List<Parameter> ps = d.parameters();
        return ps.isEmpty() ? "-" : String.join(", ", ps.stream().map(p -> p.key() + "=" + p.value()).toList());
    }
}
