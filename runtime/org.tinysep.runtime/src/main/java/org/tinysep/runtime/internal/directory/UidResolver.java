package org.tinysep.runtime.internal.directory;

import java.util.Collection;
import java.util.List;

/**
 * Resolves what the user typed to one UID: an exact UID, or a prefix of at least {@value #MIN_PREFIX} characters
 * that matches exactly one UID.
 */
public final class UidResolver {

    public static final int MIN_PREFIX = 4;
    private static final int SHOWN = 5;

    private UidResolver() {
    }

    /** @return the UIDs {@code query} names: the exact one, else those it prefixes (none if it is too short) */
    public static List<String> matches(String query, Collection<String> uids) {
        String q = query == null ? "" : query.strip();
        if (q.isEmpty()) {
            return List.of();
        }
        if (uids.contains(q)) {
            return List.of(q);
        }
        if (q.length() < MIN_PREFIX) {
            return List.of();
        }
        return uids.stream().filter(u -> u.startsWith(q)).distinct().sorted().toList();
    }

    /**
     * @param what what the UIDs identify, for messages ("device")
     * @return the single UID {@code query} names
     * @throws IllegalArgumentException if it names none or several
     */
    public static String resolve(String query, Collection<String> uids, String what) {
        String q = query == null ? "" : query.strip();
        if (q.isEmpty()) {
            throw new IllegalArgumentException("give a " + what + " uid");
        }
        List<String> found = matches(q, uids);
        if (found.size() == 1) {
            return found.get(0);
        }
        if (found.isEmpty()) {
            throw new IllegalArgumentException(q.length() < MIN_PREFIX
                    ? "no " + what + " with uid '" + q + "' (a uid prefix needs at least " + MIN_PREFIX
                            + " characters)"
                    : "no " + what + " matches '" + q + "'");
        }
        throw ambiguous(q, found);
    }

    public static IllegalArgumentException ambiguous(String query, List<String> candidates) {
        return new IllegalArgumentException("'" + query + "' is ambiguous: it matches " + candidates.size() + " ("
                + shortList(candidates) + "); give more characters");
    }

    public static String shortList(List<String> items) {
        if (items.size() <= SHOWN) {
            return String.join(", ", items);
        }
        return String.join(", ", items.subList(0, SHOWN)) + ", and " + (items.size() - SHOWN) + " more";
    }
}
