package org.tinysep.houseinformation.internal;

import java.util.ArrayList;
import java.util.Hashtable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Function;
import org.apache.felix.service.command.CommandSession;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.service.HouseInformationProvider;

/**
 * Registers the {@code tinysep:rooms}, {@code room-add}, {@code room-rename}, {@code room-link},
 * {@code room-unlink} and {@code room-remove} Gogo commands. Gogo maps command names to method names, which
 * cannot hold a '-', so each command is its own {@code Function} service. Errors become one-line messages.
 */
@Component(immediate = true, service = {})
public final class ShellFunctions {

    private final List<ServiceRegistration<?>> registrations = new ArrayList<>();

    @Activate
    public ShellFunctions(BundleContext context, @Reference HouseInformationProvider house) {
        HouseCommands c = new HouseCommands(house, () -> devicesByRoom(context));
        Map<String, Command> commands = new LinkedHashMap<>();
        commands.put("rooms", new Command("rooms", 0, 0, a -> c.rooms()));
        commands.put("room-add", new Command("room-add <name> <type>", 2, 2, a -> c.add(a.get(0), a.get(1))));
        commands.put("room-rename", new Command("room-rename <room> <new name> [new type]", 2, 3,
                a -> c.rename(a.get(0), a.get(1), a.size() > 2 ? a.get(2) : null)));
        commands.put("room-link", new Command("room-link <room> <room>", 2, 2, a -> c.link(a.get(0), a.get(1))));
        commands.put("room-unlink", new Command("room-unlink <room> <room>", 2, 2,
                a -> c.unlink(a.get(0), a.get(1))));
        commands.put("room-remove", new Command("room-remove <room>", 1, 1, a -> c.remove(a.get(0))));
        commands.forEach((name, command) -> {
            Hashtable<String, Object> props = new Hashtable<>();
            props.put("osgi.command.scope", "tinysep");
            props.put("osgi.command.function", name);
            registrations.add(context.registerService(org.apache.felix.service.command.Function.class, command,
                    props));
        });
    }

    @Deactivate
    void deactivate() {
        for (ServiceRegistration<?> r : registrations) {
            try {
                r.unregister();
            } catch (IllegalStateException ignored) {
                // the bundle is stopping
            }
        }
        registrations.clear();
    }

    private static Map<String, List<String>> devicesByRoom(BundleContext context) {
        Map<String, List<String>> byRoom = new TreeMap<>();
        try {
            for (ServiceReference<Device> ref : context.getServiceReferences(Device.class,
                    "(" + DeviceProperties.ROOM + "=*)")) {
                Device d = context.getService(ref);
                if (d != null) {
                    byRoom.computeIfAbsent(String.valueOf(ref.getProperty(DeviceProperties.ROOM)),
                            k -> new ArrayList<>()).add(d.name());
                    context.ungetService(ref);
                }
            }
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        return byRoom;
    }

    /** One command: checks the argument count, turns every failure into a one-line message. */
    private record Command(String usage, int min, int max, Function<List<String>, String> run)
            implements org.apache.felix.service.command.Function {

        @Override
        public Object execute(CommandSession session, List<Object> arguments) {
            List<String> args = arguments.stream().map(String::valueOf).toList();
            if (args.size() < min || args.size() > max) {
                throw new IllegalArgumentException("usage: " + usage);
            }
            return run.apply(args);
        }
    }
}
