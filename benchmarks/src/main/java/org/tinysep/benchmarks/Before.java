package org.tinysep.benchmarks;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The previous run's headline figures, kept beside the new ones as "before": every full run ends RESULTS.md with a
 * comment block listing its figures (one key and its values per run on a line), which the next run reads before it
 * overwrites the file. Markdown renderers do not show the block.
 */
final class Before {

    static final String START = "<!-- headline figures of this run (key, then each run's value), read by the next run"
            + " as \"before\":";
    static final String END = "-->";

    private Before() {
    }

    /** @return the comment block for {@code r}'s figures of the {@link Goals} keys and their floors */
    static String block(Report r) {
        StringBuilder b = new StringBuilder("\n").append(START).append('\n');
        for (String key : r.keys()) {
            b.append(key);
            for (double v : r.figures(key)) {
                b.append(' ').append(Double.isNaN(v) ? "NaN" : Report.f("%s", v));
            }
            b.append('\n');
        }
        return b.append(END).append('\n').toString();
    }

    /** @return the figures of an earlier RESULTS.md's block, empty when it has none; a malformed line is skipped */
    static Report read(String markdown) {
        Report before = new Report();
        int at = markdown.lastIndexOf(START);
        if (at < 0) {
            return before;
        }
        int end = markdown.indexOf(END, at + START.length());
        String body = markdown.substring(at + START.length(), end < 0 ? markdown.length() : end);
        Map<String, List<Double>> parsed = new LinkedHashMap<>();
        for (String line : body.split("\n")) {
            String[] parts = line.strip().split("\\s+");
            if (parts.length < 2 || parts[0].isEmpty()) {
                continue;
            }
            List<Double> values = new ArrayList<>();
            try {
                for (int i = 1; i < parts.length; i++) {
                    values.add(Double.parseDouble(parts[i]));
                }
            } catch (NumberFormatException e) {
                continue;
            }
            parsed.put(parts[0], values);
        }
        parsed.forEach((k, vs) -> vs.forEach(v -> before.figure(k, v)));
        return before;
    }
}
