package org.tinysep.runtime.internal.shell;

import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Map;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.runtime.internal.directory.DriverView;

/** Renders the {@code drivers}, {@code log} and {@code packets} tables (format in the bundle README). */
final class Listings {

    /** Times are shown in UTC with milliseconds, e.g. {@code 2026-11-22T11:10:00.000Z}. */
    static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("uuuu-MM-dd'T'HH:mm:ss.SSS'Z'")
            .withZone(ZoneOffset.UTC);

    private Listings() {
    }

    static String drivers(List<DriverView> drivers) {
        if (drivers.isEmpty()) {
            return "(no drivers)";
        }
        Table t = new Table("UID", "NAME", "BUNDLE", "DEVICES", "PARAMETERS");
        for (DriverView d : drivers) {
            String params = parameters(d.parameters());
            for (String e : d.errors()) {
                params += "; error: " + e;
            }
            t.row(d.uid(), d.name(), Long.toString(d.bundleId()), d.devices(), params);
        }
        return t.render();
    }

    static String events(List<EventEntry> entries) {
        return events(entries, Map.of());
    }

    /** @param names device UID → name: an origin that is a current device shows its name beside the UID */
    static String events(List<EventEntry> entries, Map<String, String> names) {
        if (entries.isEmpty()) {
            return "(no events)";
        }
        Table t = new Table("SEQ", "TIME", "KIND", "ORIGIN", "MESSAGE");
        for (EventEntry e : entries) {
            String name = e.origin() == null ? null : names.get(e.origin());
            t.row(Long.toString(e.sequence()), TIME.format(e.time()), e.kind().name(),
                    dash(e.origin()) + (name == null ? "" : " \"" + name + "\""), e.message());
        }
        return t.render();
    }

    static String packets(List<PacketEntry> entries) {
        if (entries.isEmpty()) {
            return "(no packets)";
        }
        Table t = new Table("SEQ", "TIME", "DIRECTION", "ORIGIN", "DECIMAL", "HEX", "NOTE");
        for (PacketEntry p : entries) {
            byte[] bytes = p.bytes();
            t.row(Long.toString(p.sequence()), TIME.format(p.time()), p.direction().name(), dash(p.origin()),
                    dash(p.decimal()), dash(hex(bytes)), dash(p.note()));
        }
        return t.render();
    }

    /** @return {@code key=value, key=value}, or {@code -} when there are none */
    static String parameters(List<Parameter> parameters) {
        if (parameters.isEmpty()) {
            return "-";
        }
        return String.join(", ", parameters.stream().map(p -> p.key() + "=" + p.value()).toList());
    }

    /** @return the bytes as space-separated upper-case two-digit hexadecimal, e.g. {@code AA 01 FF} */
    static String hex(byte[] bytes) {
        StringBuilder sb = new StringBuilder(bytes.length * 3);
        for (byte b : bytes) {
            if (sb.length() > 0) {
                sb.append(' ');
            }
            sb.append(Character.toUpperCase(Character.forDigit((b >> 4) & 0xF, 16)))
                    .append(Character.toUpperCase(Character.forDigit(b & 0xF, 16)));
        }
        return sb.toString();
    }

    static String dash(String s) {
        return s == null || s.isBlank() ? "-" : s;
    }
}
