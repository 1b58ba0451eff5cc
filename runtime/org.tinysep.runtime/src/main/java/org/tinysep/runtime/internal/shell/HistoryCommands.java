package org.tinysep.runtime.internal.shell;

import java.time.Clock;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import org.apache.felix.service.command.Descriptor;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.log.PacketLog;
import org.tinysep.device.support.lifecycle.Safely;
import org.tinysep.runtime.internal.directory.DeviceOrigins;
import org.tinysep.runtime.internal.directory.DeviceRecord;
import org.tinysep.runtime.internal.directory.Inventory;

/**
 * The {@code tinysep} log commands: {@code events}, {@code log} (the same; type {@code tinysep:log}, it clashes
 * with {@code felix:log}) and {@code packets}, each {@code [N] [--from T] [--to T] [--device D] [--kind K]
 * [--limit N]}. They search the logs' history on disk (and what is not written yet), newest last. Output as
 * {@link Listings}; when damaged stored lines were skipped, a last line {@code (<n> damaged lines skipped)}.
 */
// name: the component name (and PID) it had before the runtime was split into packages
@Component(name = "org.tinysep.runtime.internal.HistoryCommands",
        service = HistoryCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=log",
    "osgi.command.function=events",
    "osgi.command.function=packets"
})
public final class HistoryCommands {

    static final int DEFAULT_LINES = 20;
    static final String OPTIONS = "[N] the newest N entries (default 20); --from T, --to T a time (e.g. 14:00,"
            + " 2026-11-22T14:00, -2h); --device D a device's UID, first characters, name or node address, or a"
            + " driver's name; --kind K[,K] the kinds; --limit N the same as N";
    static final Set<String> EVENT_KINDS = names(Arrays.stream(EventKind.values()).map(Enum::name).toList());
    static final Set<String> PACKET_KINDS = names(java.util.stream.Stream.concat(
            Arrays.stream(Direction.values()).map(Enum::name),
            java.util.stream.Stream.of(LogQuery.REJECTED, LogQuery.GOOD)).toList());

    private final Inventory inventory;
    private final EventLog events;
    private final PacketLog packets;
    private final Clock clock;

    @Activate
    public HistoryCommands(@Reference(name = "inventory") Inventory inventory,
            @Reference(name = "eventLog") EventLog events, @Reference(name = "packetLog") PacketLog packets) {
        this(inventory, events, packets, Clock.systemDefaultZone());
    }

    HistoryCommands(Inventory inventory, EventLog events, PacketLog packets, Clock clock) {
        this.inventory = inventory;
        this.events = events;
        this.packets = packets;
        this.clock = clock;
    }

    /** {@code events [N] [--from T] [--to T] [--device D] [--kind K] [--limit N]}: event-log history. */
    @Descriptor("the event log, newest last (oldest first), e.g. tinysep:events --device \"Flat occupancy\""
            + " --kind DEVICE_EVENT --limit 50")
    public String events(@Descriptor(OPTIONS) String... args) {
        return ShellCommands.run("events", () -> answer(args, events.query(query(args, EVENT_KINDS)),
                list -> Listings.events(list, deviceNames()), "(no events)"));
    }

    /** {@code log ...}: the same as {@code events}. */
    @Descriptor("the same as tinysep:events (type the scope: felix:log has the same name)")
    public String log(@Descriptor(OPTIONS) String... args) {
        return events(args);
    }

    /** {@code packets [N] [--from T] [--to T] [--device D] [--kind K] [--limit N]}: packet-log history. */
    @Descriptor("the packet log (every frame received and sent, decimal and hex), newest last; --kind RECEIVED,"
            + " SENT, REJECTED or GOOD")
    public String packets(@Descriptor(OPTIONS) String... args) {
        return ShellCommands.run("packets", () -> answer(args, packets.query(query(args, PACKET_KINDS)),
                Listings::packets, "(no packets)"));
    }

    /** @return the table, or, when nothing matched and a {@code --device} names no device, that it names none */
    private <E> String answer(String[] args, LogHistory<E> history, Function<List<E>, String> table, String none) {
        if (history.entries().isEmpty()) {
            for (String ref : deviceRefs(args)) {
                if (DeviceOrigins.of(ref, inventory).size() == 1) { // only the text itself: no device or driver
                    return DeviceFilter.noMatch(ref) + ", and no log entry comes from it";
                }
            }
        }
        return render(history, table);
    }

    private static List<String> deviceRefs(String[] args) {
        List<String> refs = new ArrayList<>();
        for (int i = 0; args != null && i < args.length - 1; i++) {
            if ("--device".equals(args[i])) {
                refs.add(args[i + 1]);
            }
        }
        return refs;
    }

    /** @return UID → name of every current device, for the ORIGIN column */
    private Map<String, String> deviceNames() {
        Map<String, String> names = new HashMap<>();
        for (DeviceRecord d : inventory.devices()) {
            names.put(d.uid(), Safely.get(() -> d.device().name(), d.name()));
        }
        return names;
    }

    private LogQuery query(String[] args, Set<String> kinds) {
        return HistoryArguments.parse(args, kinds, inventory, clock, DEFAULT_LINES);
    }

    private static <E> String render(LogHistory<E> history, Function<List<E>, String> table) {
        String out = table.apply(history.entries());
        return history.damagedLines() == 0 ? out : out + "\n(" + history.damagedLines() + " damaged lines skipped)";
    }

    private static Set<String> names(java.util.List<String> names) {
        return new LinkedHashSet<>(names);
    }
}
