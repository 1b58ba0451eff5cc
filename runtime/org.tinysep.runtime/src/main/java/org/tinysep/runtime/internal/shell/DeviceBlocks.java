package org.tinysep.runtime.internal.shell;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.runtime.internal.directory.DeviceView;
import org.tinysep.runtime.internal.directory.NodeInfo;

/**
 * Renders the {@code devices} listing: per device a header line, then two-space-indented detail lines
 * (format in the bundle README; integration tests parse it, so keep it stable).
 */
final class DeviceBlocks {

    static final String INDENT = "  ";

    private DeviceBlocks() {
    }

    static String render(List<DeviceView> devices) {
        if (devices.isEmpty()) {
            return "(no devices)";
        }
        List<String> lines = new ArrayList<>();
        for (DeviceView d : devices) {
            lines.addAll(block(d));
        }
        return String.join("\n", lines);
    }

    static List<String> block(DeviceView d) {
        List<String> lines = new ArrayList<>();
        lines.add(one(d.uid() + " " + d.type() + " \"" + d.name() + "\" [" + d.status() + "] driver="
                + d.driverName()));
        lines.add(INDENT + "provides: " + (d.provides().isEmpty() ? "-" : String.join(", ", d.provides())));
        if (d.connections().isEmpty()) {
            lines.add(INDENT + "connected to: -");
        }
        for (ConnectionInfo c : d.connections()) {
            lines.add(one(INDENT + "connected to: " + c.interfaceName() + " <- " + c.providerDeviceUid() + " ("
                    + (c.vital() ? "vital" : "optional") + ")"));
        }
        if (!d.node().isEmpty()) {
            lines.add(one(INDENT + "node: " + node(d.node())));
        }
        lines.add(one(INDENT + "parameters: " + Listings.parameters(d.parameters())));
        if (!d.functions().isEmpty()) {
            lines.add(one(INDENT + "functions: "
                    + String.join(", ", d.functions().stream().map(DeviceFunction::name).toList())));
        }
        for (String e : d.errors()) {
            lines.add(one(INDENT + "error: " + e));
        }
        return lines;
    }

    /** @return the present parts of {@code types=a,b, address=..., room=...} */
    static String node(NodeInfo n) {
        List<String> parts = new ArrayList<>();
        if (!n.types().isEmpty()) {
            parts.add("types=" + String.join(",", n.types()));
        }
        if (!n.address().isEmpty()) {
            parts.add("address=" + n.address());
        }
        if (!n.room().isEmpty()) {
            parts.add("room=" + n.room());
        }
        return String.join(", ", parts);
    }

    /** Keeps a line a line: a device's text with line breaks must not split its block. */
    private static String one(String line) {
        return line.replaceAll("[\\r\\n\\t]+", " ");
    }
}
