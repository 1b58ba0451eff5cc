package org.tinysep.runtime.internal.shell;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.device.support.lifecycle.Safely;

/**
 * A plain-text table: a header row, then one row per line, columns separated by {@code " | "} and padded to a
 * common width, the last column unpadded. Cells are made single-line; {@code |} in any but the last column becomes
 * {@code /}, so splitting a line on {@code " | "} with a limit of the column count always works.
 */
final class Table {

    static final String SEPARATOR = " | ";

    private final List<String[]> rows = new ArrayList<>();
    private final int columns;

    Table(String... header) {
        columns = header.length;
        rows.add(header);
    }

    Table row(String... cells) {
        if (cells.length != columns) {
            throw new IllegalArgumentException("expected " + columns + " cells, got " + cells.length);
        }
        String[] clean = new String[columns];
        for (int i = 0; i < columns; i++) {
            String c = Safely.oneLine(cells[i]);
            clean[i] = i < columns - 1 ? c.replace('|', '/') : c;
        }
        rows.add(clean);
        return this;
    }

    String render() {
        int[] widths = new int[columns];
        for (String[] r : rows) {
            for (int i = 0; i < columns - 1; i++) {
                widths[i] = Math.max(widths[i], r[i].length());
            }
        }
        StringBuilder sb = new StringBuilder();
        for (String[] r : rows) {
            if (sb.length() > 0) {
                sb.append('\n');
            }
            StringBuilder line = new StringBuilder();
            for (int i = 0; i < columns - 1; i++) {
                line.append(r[i]).append(" ".repeat(widths[i] - r[i].length())).append(SEPARATOR);
            }
            line.append(r[columns - 1]);
            sb.append(line.toString().stripTrailing());
        }
        return sb.toString();
    }
}
