package org.tinysep.drivers.internal;

import java.util.ArrayList;
import java.util.List;

/** A plain-text table for the shell: columns separated by {@code " | "}, padded, the last column unpadded. */
final class TextTable {

    private final List<String[]> rows = new ArrayList<>();

    TextTable(String... header) {
        rows.add(header);
    }

    TextTable row(String... cells) {
        String[] clean = new String[cells.length];
        for (int i = 0; i < cells.length; i++) {
            clean[i] = cells[i] == null ? "-" : cells[i].replaceAll("\\s+", " ").strip();
        }
        rows.add(clean);
        return this;
    }

    String render() {
        int[] w = new int[rows.get(0).length];
        for (String[] r : rows) {
            for (int i = 0; i < r.length - 1; i++) {
                w[i] = Math.max(w[i], r[i].length());
            }
        }
        StringBuilder sb = new StringBuilder();
        for (String[] r : rows) {
            StringBuilder line = new StringBuilder();
            for (int i = 0; i < r.length; i++) {
                line.append(r[i]).append(i == r.length - 1 ? "" : " ".repeat(w[i] - r[i].length()) + " | ");
            }
            sb.append(sb.length() == 0 ? "" : "\n").append(line.toString().stripTrailing());
        }
        return sb.toString();
    }
}
