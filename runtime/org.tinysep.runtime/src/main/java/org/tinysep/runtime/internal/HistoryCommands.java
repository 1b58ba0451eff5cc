package org.tinysep.runtime.internal;

import java.time.Clock;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.Set;
import java.util.function.Function;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.log.PacketLog;

/**
 * The {@code tinysep} log commands: {@code events}, {@code log} (the same; type {@code tinysep:log}, it clashes
 * with {@code felix:log}) and {@code packets}, each {@code [N] [--from T] [--to T] [--device D] [--kind K]
 * [--limit N]}. They search the logs' history on disk (and what is not written yet), newest last. Output as
 * {@link Listings}; when damaged stored lines were skipped, a last line {@code (<n> damaged lines skipped)}.
 */
@Component(service = HistoryCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=log",
    "osgi.command.function=events",
    "osgi.command.function=packets"
})
public final class HistoryCommands {

    static final int DEFAULT_LINES = 20;
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
    public String events(String... args) {
        return ShellCommands.run("events", () -> render(events.query(query(args, EVENT_KINDS)), Listings::events));
    }

    /** {@code log ...}: the same as {@code events}. */
    public String log(String... args) {
        return events(args);
    }

    /** {@code packets [N] [--from T] [--to T] [--device D] [--kind K] [--limit N]}: packet-log history. */
    public String packets(String... args) {
        return ShellCommands.run("packets",
                () -> render(packets.query(query(args, PACKET_KINDS)), Listings::packets));
    }

    private LogQuery query(String[] args, Set<String> kinds) {
        return HistoryArguments.parse(args, kinds, inventory, clock, DEFAULT_LINES);
    }

    private static <E> String render(LogHistory<E> history, Function<java.util.List<E>, String> table) {
        String out = table.apply(history.entries());
        return history.damagedLines() == 0 ? out : out + "\n(" + history.damagedLines() + " damaged lines skipped)";
    }

    private static Set<String> names(java.util.List<String> names) {
        return new LinkedHashSet<>(names);
    }
}
