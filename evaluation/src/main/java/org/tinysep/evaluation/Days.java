package org.tinysep.evaluation;

import java.time.LocalDateTime;

/** A home cut to its first days (the CI smoke test's short window). */
final class Days {

    private Days() {
    }

    static Home first(Home h, int days) {
        LocalDateTime until = h.events().get(0).time().toLocalDate().plusDays(days).atStartOfDay();
        return new Home(h.name() + "-first-" + days + "-days",
                h.events().stream().filter(e -> e.time().isBefore(until)).toList(),
                h.labels().stream().filter(l -> l.start().isBefore(until)).toList(), h.mapping(), h.house(), h.nodes(),
                h.residents());
    }
}
