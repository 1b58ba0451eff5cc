package org.tinysep.web.api.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.api.device.Parameter;

/**
 * The choices of an enumerated parameter, read from its description: drivers describe such a parameter by
 * starting the description with its values, e.g. {@code "OUTER (to the outside; …) or INNER"},
 * {@code "INSIDE or OUTSIDE the flat"}, {@code "REAL, EXTERNAL or OFF"}, {@code "true or false; …"} (upper-case
 * constants or true/false, each optionally followed by a note in parentheses, separated by commas and a final
 * "or"). Any other description gives no choices (a text field).
 */
final class ParameterOptions {

    private static final String WORD = "(?:[A-Z][A-Z0-9_]+|true|false)";
    private static final String ITEM = WORD + "(?: \\([^)]*\\))?";
    private static final Pattern LIST = Pattern.compile("^(" + ITEM + "(?:, " + ITEM + ")* or " + WORD + ")(?=$|[\\s;,.:(])");
    private static final Pattern WORDS = Pattern.compile(WORD);

    private ParameterOptions() {
    }

    /** @return the values the parameter may take, empty when it is free text or read-only */
    static List<String> of(Parameter p) {
        if (!p.writable()) {
            return List.of();
        }
        Matcher m = LIST.matcher(p.description());
        if (!m.find()) {
            return List.of();
        }
        List<String> out = new ArrayList<>();
        Matcher w = WORDS.matcher(m.group(1).replaceAll("\\([^)]*\\)", ""));
        while (w.find()) {
            if (!out.contains(w.group())) {
                out.add(w.group());
            }
        }
        return List.copyOf(out);
    }
}
