package org.tinysep.houseinformation.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * The configured room placement rules: comma- or newline-separated entries {@code <node address>=<room>}. A node
 * address is an AmICA {@code NG.ADDR} (decimal, 0..255 each) or a Sun SPOT {@code XXXX.XXXX.XXXX.XXXX} (hex).
 * Bad entries are collected as clear messages; the good ones still apply.
 */
final class PlacementRules {

    private static final Pattern AMICA = Pattern.compile("(\\d{1,3})\\.(\\d{1,3})");
    private static final Pattern SUN_SPOT = Pattern.compile("\\p{XDigit}{4}(\\.\\p{XDigit}{4}){3}");

    /** One rule: devices of node {@code address} go to {@code room} (a room name or UID). */
    record Rule(String address, String room) {
        @Override
        public String toString() {
            return address + "=" + room;
        }
    }

    private final Map<String, Rule> byAddress;
    private final List<String> errors;

    private PlacementRules(Map<String, Rule> byAddress, List<String> errors) {
        this.byAddress = byAddress;
        this.errors = errors;
    }

    static PlacementRules parse(String text) {
        Map<String, Rule> rules = new LinkedHashMap<>();
        List<String> errors = new ArrayList<>();
        for (String raw : (text == null ? "" : text).split("[,\\r\\n]+")) {
            String entry = raw.strip();
            if (entry.isEmpty()) {
                continue;
            }
            int eq = entry.indexOf('=');
            if (eq < 0) {
                errors.add("placement entry '" + entry + "' has no '=': expected <node address>=<room>");
                continue;
            }
            String room = entry.substring(eq + 1).strip();
            Optional<String> address = normalise(entry.substring(0, eq));
            if (address.isEmpty()) {
                errors.add("placement entry '" + entry + "': '" + entry.substring(0, eq).strip()
                        + "' is not a node address (AmICA NG.ADDR like 1.17, or Sun SPOT XXXX.XXXX.XXXX.XXXX)");
            } else if (room.isEmpty()) {
                errors.add("placement entry '" + entry + "' names no room");
            } else if (rules.containsKey(address.get())) {
                errors.add("placement entry '" + entry + "': node " + address.get() + " is already placed by '"
                        + rules.get(address.get()) + "'; the first entry applies");
            } else {
                rules.put(address.get(), new Rule(address.get(), room));
            }
        }
        return new PlacementRules(Map.copyOf(rules), List.copyOf(errors));
    }

    /** @return the address in the form devices publish it ({@code 1.17}, upper-case Sun SPOT hex), if valid */
    static Optional<String> normalise(String address) {
        String a = address == null ? "" : address.strip();
        var amica = AMICA.matcher(a);
        if (amica.matches()) {
            int ng = Integer.parseInt(amica.group(1));
            int addr = Integer.parseInt(amica.group(2));
            return ng <= 255 && addr <= 255 ? Optional.of(ng + "." + addr) : Optional.empty();
        }
        return SUN_SPOT.matcher(a).matches() ? Optional.of(a.toUpperCase(Locale.ROOT)) : Optional.empty();
    }

    /** @return the rule for a device's {@code tinysep.node.address} value, if any */
    Optional<Rule> ruleFor(Object address) {
        return address == null ? Optional.empty()
                : normalise(address.toString()).map(byAddress::get);
    }

    /** @return the number of good rules */
    int size() {
        return byAddress.size();
    }

    /** @return one clear message per bad entry, in input order */
    List<String> errors() {
        return errors;
    }
}
