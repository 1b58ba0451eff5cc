package org.tinysep.houseinformation.internal;

import java.util.ArrayList;
import java.util.Hashtable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.BiFunction;
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
import org.tinysep.device.support.lifecycle.ServiceUse;

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
        String room = "<room>: a room's name (any case), UID or unique UID prefix of 4+ characters";
        String type = "<type>: the room type, e.g. Bathroom, Bedroom, Hall, Kitchen, Living room (Inactivity"
                + " Recognition's limits go by type); " + RoomTypes.NEW_TYPE + ": accept a type no room has yet";
        Map<String, Command> commands = new LinkedHashMap<>();
        commands.put("rooms", new Command("rooms", "the house plan: every room with its type, neighbours and"
                + " devices", List.of(), 0, 0, (a, n) -> c.rooms()));
        commands.put("room-add", new Command("room-add <name> <type> [" + RoomTypes.NEW_TYPE + "]", "adds a room",
                List.of("<name>: the room's name, e.g. \"Guest room\"", type), 2, 2,
                (a, n) -> c.add(a.get(0), a.get(1), n)));
        commands.put("room-rename", new Command("room-rename <room> <new name> [new type] [" + RoomTypes.NEW_TYPE
                + "]", "renames a room, and changes its type when one is given", List.of(room, type), 2, 3,
                (a, n) -> c.rename(a.get(0), a.get(1), a.size() > 2 ? a.get(2) : null, n)));
        commands.put("room-link", new Command("room-link <room> <room>", "makes two rooms neighbours (a person"
                + " can walk from one to the other)", List.of(room), 2, 2, (a, n) -> c.link(a.get(0), a.get(1))));
        commands.put("room-unlink", new Command("room-unlink <room> <room>", "makes two rooms no longer neighbours",
                List.of(room), 2, 2, (a, n) -> c.unlink(a.get(0), a.get(1))));
        commands.put("room-remove", new Command("room-remove <room>", "removes a room; its devices are no longer"
                + " placed", List.of(room), 1, 1, (a, n) -> c.remove(a.get(0))));
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

    static Map<String, List<String>> devicesByRoom(BundleContext context) {
        Map<String, List<String>> byRoom = new TreeMap<>();
        try {
            for (ServiceReference<Device> ref : context.getServiceReferences(Device.class,
                    "(" + DeviceProperties.ROOM + "=*)")) {
                // read and given back through ServiceObjects: no use left behind per device (Felix scans every
                // bundle's uses on each unregistration, so n left here made stopping n devices cost n²)
                String name = ServiceUse.with(context, ref, Device::name, null);
                if (name != null) {
                    byRoom.computeIfAbsent(String.valueOf(ref.getProperty(DeviceProperties.ROOM)),
                            k -> new ArrayList<>()).add(name);
                }
            }
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        return byRoom;
    }

    /**
     * One command: {@code --help} (or a wrong argument count) gives its usage, what it does and what each argument
     * means; every failure becomes a one-line message. Gogo's {@code help} describes only commands that are Java
     * methods, and a method name cannot hold a '-': so these explain themselves.
     */
    record Command(String usage, String description, List<String> arguments, int min, int max,
            BiFunction<List<String>, Boolean, String> run) implements org.apache.felix.service.command.Function {

        @Override
        public Object execute(CommandSession session, List<Object> arguments) {
            List<String> all = arguments.stream().map(String::valueOf).toList();
            if (all.contains("--help")) {
                return help();
            }
            List<String> args = all.stream().filter(a -> !RoomTypes.NEW_TYPE.equals(a)).toList();
            if (args.size() < min || args.size() > max) {
                throw new IllegalArgumentException((args.size() < min ? "missing arguments" : "too many arguments")
                        + "; usage: " + usage + " (tinysep:" + usage.split(" ")[0] + " --help explains)");
            }
            return run.apply(args, all.contains(RoomTypes.NEW_TYPE));
        }

        /** @return the usage line, the description and one line per argument */
        String help() {
            StringBuilder s = new StringBuilder("tinysep:" + usage + "\n  " + description);
            arguments.forEach(a -> s.append("\n  ").append(a));
            return s.toString();
        }
    }
}
