package org.tinysep.amica.busradio.base;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.Parameter;

/**
 * Keeps a node's type while devices depend on it: a keep-alive is not authenticated, so one
 * datagram claiming other node types must not re-type a node and so remove the devices that watch the person. A
 * disagreeing keep-alive is counted, its types are held as <em>pending</em>, and each distinct claim is reported
 * once (at most {@link #MAX_REPORTS} per node: a forger cycling through type sets cannot flood the event log); the
 * installer applies the pending types with the bus device's function {@value #ACCEPT}. A later keep-alive with
 * the known types clears the pending ones: only what the node itself keeps claiming can be confirmed.
 * Thread-safe.
 */
final class NodeTypeGuard {

    /** The bus device function that applies the pending types. */
    static final String ACCEPT = "acceptNodeTypes";
    /** Distinct claims reported per node; later ones are only counted. */
    static final int MAX_REPORTS = 8;
    /** The start of every report (the caregiver-visible signals of docs/security.md, "Node identity"). */
    static final String PREFIX = "Node type mismatch: ";

    /** What a disagreeing keep-alive claimed, and where it came from. */
    record Claim(Set<String> types, KeepAlive keepAlive, String from) {
    }

    private final Set<Set<String>> reported = new HashSet<>();
    private long mismatches;
    private Claim pending;

    /**
     * Counts a disagreeing keep-alive and holds its types.
     *
     * @return whether to report it: the first of its type set (and within {@link #MAX_REPORTS})
     */
    synchronized boolean mismatch(Claim claim) {
        mismatches++;
        pending = claim;
        return reported.size() < MAX_REPORTS && reported.add(claim.types());
    }

    /** @return whether this was the last claim this node reports (later distinct ones are only counted) */
    synchronized boolean reportsExhausted() {
        return reported.size() >= MAX_REPORTS;
    }

    /** A keep-alive with the known types: what was pending is not what the node says now. */
    synchronized void agreed() {
        pending = null;
    }

    /** @return the pending claim, now applied (null when none); the reports start afresh for the new types */
    synchronized Claim take() {
        Claim c = pending;
        pending = null;
        if (c != null) {
            reported.clear();
        }
        return c;
    }

    synchronized long mismatches() {
        return mismatches;
    }

    synchronized Claim pending() {
        return pending;
    }

    /** @return {@code typeMismatches} and {@code pendingNodeTypes} */
    List<Parameter> parameters() {
        Claim c = pending();
        return List.of(Parameter.readOnly("typeMismatches", mismatches(),
                        "keep-alives whose node types disagreed with the known ones (not applied)"),
                Parameter.readOnly("pendingNodeTypes", c == null ? "" : String.join(",", c.types()) + " (from "
                        + c.from() + ")", "node types a keep-alive claimed; '" + ACCEPT + "' applies them"));
    }

    /**
     * The PROBLEM entry, in plain words.
     *
     * @param node       e.g. "AmICA node 1.40"
     * @param dependents the devices that use the node, e.g. "'Movement 1.40' in Bathroom"
     * @param uid        the bus device's UID, for the installer's command
     * @param last       whether later distinct claims of this node will only be counted
     */
    static String problem(String node, Set<String> known, Claim claim, String dependents, String uid,
            boolean last) {
        return PREFIX + node + " is a " + words(known) + " node (used by " + dependents + "), but a keep-alive from "
                + claim.from() + " claims it is a " + words(claim.types()) + " node. Nothing was changed: the node"
                + " keeps its type and its devices keep watching. This frame is not authenticated: it may come from"
                + " another program sending in the node's name. If the node really was changed (new firmware, or"
                + " another node given this address), the installer confirms with: tinysep:invoke " + uid + " "
                + ACCEPT + (last ? ". Further different claims for this node are only counted (typeMismatches)."
                        : ".");
    }

    /** @return the devices among a node's listeners, e.g. "'Movement 1.40' in Bathroom", for the report */
    static String dependents(List<?> listeners) {
        List<String> names = new ArrayList<>();
        for (Object l : listeners) {
            if (l instanceof Device d) {
                String room = d.parameters().stream().filter(p -> p.key().equals("room")).map(Parameter::value)
                        .findFirst().orElse("");
                int cut = room.indexOf(" ("); // "Bathroom (uid)"
                names.add("'" + d.name() + "'" + (room.isEmpty() ? " (not placed in a room)"
                        : " in " + (cut > 0 ? room.substring(0, cut) : room)));
            }
        }
        return names.isEmpty() ? "a device that is being updated" : String.join(", ", names);
    }

    private static String words(Set<String> types) {
        return types.isEmpty() ? "typeless" : String.join(" and ", new java.util.TreeSet<>(types));
    }
}
