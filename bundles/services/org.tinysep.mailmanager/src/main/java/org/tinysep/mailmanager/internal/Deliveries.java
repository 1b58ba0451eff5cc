package org.tinysep.mailmanager.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailDelivery.Outcome;

/**
 * What became of the last {@value #KEPT} messages (delivery you can see), for
 * {@code MailManagerProvider.delivery/deliveries}, the alert service and the {@code tinysep:mails} command. In
 * memory only: the spool and the event log are the durable record.
 */
final class Deliveries {

    static final int KEPT = 100;

    private final Map<String, MailDelivery> byId = new LinkedHashMap<>(16, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, MailDelivery> eldest) {
            return size() > KEPT;
        }
    };

    /** Records the outcome of {@code m}; {@code to} and {@code at} as known now. */
    synchronized void update(MailMessage m, List<String> to, Outcome outcome, String detail, Instant at) {
        String id = Long.toString(m.id());
        MailDelivery old = byId.get(id);
        List<String> recipients = old != null && !old.to().isEmpty() ? old.to() : to;
        byId.put(id, new MailDelivery(id, m.subject(), recipients, m.queuedAt(), outcome, detail, at));
    }

    synchronized Optional<MailDelivery> get(String id) {
        return Optional.ofNullable(byId.get(id));
    }

    /** @return oldest first */
    synchronized List<MailDelivery> all() {
        return new ArrayList<>(byId.values());
    }
}
