package org.tinysep.sunspot.person.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.tinysep.sunspot.protocol.SunSpotAddress;

/**
 * The configured wearers, {@code <node address>=<name>} entries separated by commas or new lines (e.g.
 * {@code 0014.4F01.0000.0A04=Anna}). Addresses in any case; names at most {@value SunSpotPersonDevice#MAX_NAME}
 * characters. Each bad entry is a problem in words; the others still apply; a node named twice keeps the first.
 */
record PersonRules(Map<String, String> byAddress, List<String> problems) {

    static PersonRules parse(String text) {
        Map<String, String> rules = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        for (String entry : (text == null ? "" : text).split("[,\\n]")) {
            String e = entry.strip();
            if (e.isEmpty()) {
                continue;
            }
            int eq = e.indexOf('=');
            String name = eq < 0 ? "" : e.substring(eq + 1).strip();
            Optional<String> address = eq < 0 ? Optional.empty() : address(e.substring(0, eq).strip());
            if (eq < 0 || name.isEmpty()) {
                problems.add("persons entry '" + e + "' is not <node address>=<name>");
            } else if (address.isEmpty()) {
                problems.add("persons entry '" + e + "': '" + e.substring(0, eq).strip()
                        + "' is not a Sun SPOT address (XXXX.XXXX.XXXX.XXXX, hex)");
            } else if (name.length() > SunSpotPersonDevice.MAX_NAME) {
                problems.add("persons entry '" + e + "': the name is longer than " + SunSpotPersonDevice.MAX_NAME
                        + " characters");
            } else if (rules.putIfAbsent(address.get(), name) != null) {
                problems.add("persons entry '" + e + "': node " + address.get() + " is named twice; the first, "
                        + rules.get(address.get()) + ", applies");
            }
        }
        return new PersonRules(Map.copyOf(rules), List.copyOf(problems));
    }

    /** @return the name configured for this node address, if any */
    Optional<String> nameOf(String nodeAddress) {
        return address(nodeAddress).map(byAddress::get);
    }

    private static Optional<String> address(String text) {
        try {
            return Optional.of(SunSpotAddress.parse(text).toString());
        } catch (RuntimeException e) {
            return Optional.empty();
        }
    }
}
