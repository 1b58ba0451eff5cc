package org.tinysep.simulator.agent;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;

/** A parsed scenario: its steps in time order (stable for equal times) and the names of its pets. */
public record Scenario(List<Step> steps, Set<String> pets) {

    public Scenario {
        List<Step> sorted = new ArrayList<>(steps);
        sorted.sort(Comparator.comparingInt(Step::secondOfDay));
        steps = List.copyOf(sorted);
        pets = Set.copyOf(pets);
    }

    /** @return the agents (people and pets) in order of first appearance */
    public List<String> agents() {
        return steps.stream().map(Step::agent).filter(a -> a != null).distinct().toList();
    }
}
