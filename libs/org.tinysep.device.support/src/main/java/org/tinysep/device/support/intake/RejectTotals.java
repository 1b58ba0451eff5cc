package org.tinysep.device.support.intake;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.device.Parameter;

/**
 * The {@code rejected} total of a driver's parameters: the sum of every {@code rejected.<reason>} counter it shows,
 * wherever each comes from (the reject counter's reasons, the source gate's {@code source_not_allowed} and
 * {@code rejected.rate_limited}, the node table's {@code node_cap}), so the total always equals what the counters
 * below it add up to (the total left out {@code node_cap}).
 */
public final class RejectTotals {

    /** The key of the total. */
    public static final String TOTAL = "rejected";
    private static final String PREFIX = TOTAL + ".";

    private RejectTotals() {
    }

    /**
     * @param parameters a driver's parameters, with or without a {@code rejected} entry (whose description is kept)
     * @return the same parameters with {@code rejected} (in place of the old one, else before the first
     *         {@code rejected.<reason>}, else at the end) set to the sum of the {@code rejected.<reason>} values
     */
    public static List<Parameter> summed(List<Parameter> parameters) {
        long sum = 0;
        String description = "rejected in total";
        for (Parameter p : parameters) {
            if (p.key().equals(TOTAL) && !p.description().isEmpty()) {
                description = p.description();
            }
            if (p.key().startsWith(PREFIX) && p.value().chars().allMatch(Character::isDigit) && !p.value().isEmpty()) {
                sum += Long.parseLong(p.value());
            }
        }
        Parameter total = Parameter.readOnly(TOTAL, sum, description);
        List<Parameter> out = new ArrayList<>(parameters.size() + 1);
        boolean placed = false;
        for (Parameter p : parameters) {
            if (p.key().equals(TOTAL)) {
                if (!placed) {
                    out.add(total);
                    placed = true;
                }
            } else {
                if (!placed && p.key().startsWith(PREFIX)) {
                    out.add(total);
                    placed = true;
                }
                out.add(p);
            }
        }
        if (!placed) {
            out.add(total);
        }
        return out;
    }
}
