package org.tinysep.evaluation;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Pattern;
import org.tinysep.simulator.replay.Label;

/**
 * Which labelled activities mean "away from home" and "asleep". The harness counts {@code Leaving} and
 * {@code Sleeping} (Ordonez's names); other recordings name them otherwise ({@code Leave_Home}, {@code Sleep},
 * {@code go to bed}, {@code Out}, ...), and a home whose away and sleep labels were not recognised would have
 * collapses drawn while the resident is out or asleep and away time counted as blind. So activity names are matched
 * by words (case-insensitive; {@code --away-labels} and {@code --sleep-labels} replace the patterns) and the
 * matching labels are renamed {@code Leaving} / {@code Sleeping}; away wins when both match. {@code Bed_to_Toilet}
 * is neither: it is getting up.
 */
final class LabelWords {

    static final String AWAY = "leav|left[ _-]?(the[ _-]?)?(home|house)|\\baway\\b|outside|\\bgo(ing)?[ _-]?out\\b"
            + "|^out$|out[ _-]of[ _-](the[ _-])?(home|house)|not[ _-]at[ _-]home|absent";
    static final String SLEEP = "sleep|\\bgo(ing)?[ _-]?to[ _-]?bed\\b|\\bnap(ping)?\\b|bedtime|\\bin[ _-]bed\\b";

    private final Pattern away;
    private final Pattern sleep;

    LabelWords(String away, String sleep) {
        this.away = Pattern.compile(away, Pattern.CASE_INSENSITIVE);
        this.sleep = Pattern.compile(sleep, Pattern.CASE_INSENSITIVE);
    }

    static LabelWords defaults() {
        return new LabelWords(AWAY, SLEEP);
    }

    /** @return {@code Leaving}, {@code Sleeping} or the activity as it is */
    String meaning(String activity) {
        if (away.matcher(activity).find()) {
            return "Leaving";
        }
        return sleep.matcher(activity).find() ? "Sleeping" : activity;
    }

    /** @return the labels with away and sleep activities renamed {@code Leaving} / {@code Sleeping} */
    List<Label> normalise(List<Label> labels) {
        return labels.stream().map(l -> new Label(l.start(), l.end(), meaning(l.activity()), l.resident())).toList();
    }

    /** @return in words which activity names were taken for away and asleep, and which for neither */
    String describe(List<Label> labels) {
        Map<String, Integer> counts = new TreeMap<>();
        labels.forEach(l -> counts.merge(l.activity(), 1, Integer::sum));
        StringBuilder awayNames = new StringBuilder();
        StringBuilder sleepNames = new StringBuilder();
        StringBuilder other = new StringBuilder();
        counts.forEach((name, n) -> {
            String m = meaning(name);
            StringBuilder b = m.equals("Leaving") ? awayNames : m.equals("Sleeping") ? sleepNames : other;
            b.append(b.length() == 0 ? "" : ", ").append(name).append(" (").append(n).append(')');
        });
        String s = "labels taken for away: " + (awayNames.length() == 0 ? "none" : awayNames) + "; for asleep: "
                + (sleepNames.length() == 0 ? "none" : sleepNames) + "; at home and awake: "
                + (other.length() == 0 ? "none" : other);
        return awayNames.length() == 0 || sleepNames.length() == 0 ? s + "\nwarning: no label was taken for "
                + (awayNames.length() == 0 ? "away" : "asleep") + ": collapses may be drawn while the resident is "
                + (awayNames.length() == 0 ? "out" : "asleep") + " (give --away-labels / --sleep-labels <regex>)" : s;
    }
}
