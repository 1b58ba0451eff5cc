package org.tinysep.runtime.internal.backup;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import org.tinysep.api.backup.ComponentBackup;

/**
 * Writes a backup file without JAXB: the same bytes JAXB's formatted output gives for {@link BackupXml}
 * ({@code BackupXmlWriterTest} compares them), at a fraction of the cost. Every new device is saved once, so a
 * burst of 20,000 devices meant 20,000 marshals on the backup writer's thread, its largest cost (JFR).
 * Files of exactly this shape are read back by {@link BackupXmlReader}; anything else by JAXB.
 */
final class BackupXmlWriter {

    private BackupXmlWriter() {
    }

    static byte[] write(ComponentBackup b) {
        StringBuilder x = new StringBuilder(640);
        x.append("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n<backup version=\"1\" kind=\"");
        escape(x, b.kind().name(), true).append("\">\n");
        element(x, "uid", b.uid());
        element(x, "driverUid", b.driverUid());
        element(x, "driverName", b.driverName());
        element(x, "type", b.type());
        element(x, "name", b.name());
        element(x, "savedAt", b.savedAt().toString());
        element(x, "nodeAddress", b.nodeAddress());
        list(x, "nodeTypes", "nodeType", b.nodeTypes());
        if (b.lastSeen() != null) {
            element(x, "lastSeen", b.lastSeen().toString());
        }
        entries(x, "parameters", "parameter", b.parameters());
        entries(x, "state", "value", b.state());
        x.append("</backup>\n");
        return x.toString().getBytes(StandardCharsets.UTF_8);
    }

    private static void element(StringBuilder x, String tag, String text) {
        x.append("    <").append(tag).append('>');
        escape(x, text, false).append("</").append(tag).append(">\n");
    }

    private static void list(StringBuilder x, String wrapper, String tag, List<String> items) {
        if (items.isEmpty()) {
            x.append("    <").append(wrapper).append("/>\n");
            return;
        }
        x.append("    <").append(wrapper).append(">\n");
        for (String item : items) {
            x.append("    ");
            element(x, tag, item);
        }
        x.append("    </").append(wrapper).append(">\n");
    }

    private static void entries(StringBuilder x, String wrapper, String tag, Map<String, String> entries) {
        if (entries.isEmpty()) {
            x.append("    <").append(wrapper).append("/>\n");
            return;
        }
        x.append("    <").append(wrapper).append(">\n");
        entries.forEach((k, v) -> {
            x.append("        <").append(tag).append(" key=\"");
            escape(x, k, true).append("\">");
            escape(x, v, false).append("</").append(tag).append(">\n");
        });
        x.append("    </").append(wrapper).append(">\n");
    }

    /**
     * As JAXB escapes: {@code & < >} and a carriage return always, {@code "} and a line feed in attributes;
     * everything else as it is.
     */
    private static StringBuilder escape(StringBuilder x, String s, boolean attribute) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '&' -> x.append("&amp;");
                case '<' -> x.append("&lt;");
                case '>' -> x.append("&gt;");
                case '"' -> x.append(attribute ? "&quot;" : "\"");
                case '\n' -> x.append(attribute ? "&#10;" : "\n");
                case '\r' -> x.append("&#13;");
                default -> x.append(c);
            }
        }
        return x;
    }
}
