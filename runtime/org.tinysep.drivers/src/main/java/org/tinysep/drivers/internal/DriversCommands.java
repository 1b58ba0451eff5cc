package org.tinysep.drivers.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;

/**
 * {@code tinysep:drivers [reload | enable <bsn> | disable <bsn>]}. Ranked above the device manager's older
 * {@code tinysep:drivers} (a plain list of Driver services), whose content it includes: each entry shows the Driver
 * services its bundle registers, and bundles with drivers that are not in the list follow at the end.
 */
@Component(service = DriversCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=drivers",
    "service.ranking:Integer=10"
})
public final class DriversCommands {

    private final BundleContext context;
    private final DriversList list;

    @Activate
    public DriversCommands(BundleContext context, @Reference DriversList list) {
        this.context = context;
        this.list = list;
    }

    /** {@code drivers}: the list with each entry's status and drivers. */
    public String drivers() {
        Map<String, TreeSet<String>> drivers = driversByBundle();
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"application", "enabled", "status", "drivers", "file"});
        for (DriverEntry e : list.entries()) {
            TreeSet<String> names = drivers.remove(e.symbolicName());
            rows.add(new String[] {e.key(), e.enabled() ? "yes" : "no", e.status(),
                names == null ? "-" : String.join(", ", names), e.location()});
        }
        StringBuilder out = new StringBuilder("Drivers list " + list.path() + "\n").append(table(rows));
        if (!drivers.isEmpty()) {
            out.append("\nNot in the list (hot-deployed or platform bundles):");
            drivers.forEach((bsn, names) -> out.append("\n  ").append(bsn).append(": ").append(String.join(", ", names)));
        }
        return out.toString();
    }

    /** {@code drivers reload} (or {@code list}). */
    public String drivers(String action) {
        return switch (action.toLowerCase(Locale.ROOT)) {
            case "reload" -> {
                List<String> changes = list.reload();
                yield changes.isEmpty() ? "Drivers list reloaded: nothing to change" : "Drivers list reloaded:\n  "
                        + String.join("\n  ", changes);
            }
            case "list" -> drivers();
            default -> throw new IllegalArgumentException("unknown action '" + action
                    + "': use tinysep:drivers [reload | enable <name> | disable <name>]");
        };
    }

    /** {@code drivers enable|disable <bsn>}. */
    public String drivers(String action, String bsn) {
        boolean enable = switch (action.toLowerCase(Locale.ROOT)) {
            case "enable" -> true;
            case "disable" -> false;
            default -> throw new IllegalArgumentException("unknown action '" + action
                    + "': use tinysep:drivers enable <name> or tinysep:drivers disable <name>");
        };
        return String.join("\n", list.setEnabled(bsn, enable));
    }

    /** @return bundle symbolic name → names of the Driver services it registers */
    private Map<String, TreeSet<String>> driversByBundle() {
        Map<String, TreeSet<String>> byBundle = new TreeMap<>();
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(Driver.class.getName(), null);
            for (ServiceReference<?> ref : refs == null ? new ServiceReference<?>[0] : refs) {
                Bundle b = ref.getBundle();
                if (b != null) {
                    byBundle.computeIfAbsent(String.valueOf(b.getSymbolicName()), k -> new TreeSet<>())
                            .add(String.valueOf(ref.getProperty(DeviceProperties.DRIVER_NAME)));
                }
            }
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        return byBundle;
    }

    private static String table(List<String[]> rows) {
        int[] w = new int[rows.get(0).length];
        rows.forEach(r -> {
            for (int i = 0; i < r.length; i++) {
                w[i] = Math.max(w[i], r[i].length());
            }
        });
        StringBuilder sb = new StringBuilder();
        for (String[] r : rows) {
            StringBuilder line = new StringBuilder();
            for (int i = 0; i < r.length; i++) {
                line.append(i == r.length - 1 ? r[i] : String.format("%-" + w[i] + "s | ", r[i]));
            }
            sb.append(sb.length() == 0 ? "" : "\n").append(line.toString().stripTrailing());
        }
        return sb.toString();
    }
}
