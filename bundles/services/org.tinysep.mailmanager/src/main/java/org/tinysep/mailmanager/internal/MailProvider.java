package org.tinysep.mailmanager.internal;

import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.device.support.lifecycle.Listeners;

/**
 * The MailManagerProvider side of the device: a separate object because {@code MailManagerProvider.status()} and
 * {@code Device.status()} differ in type.
 */
final class MailProvider implements MailManagerProvider {

    /** Queues a message: (to, subject, body) → id. */
    interface Sender {
        String send(List<String> to, String subject, String body);
    }

    private final String uid;
    private final Sender send;
    private final Supplier<MailStatus> status;
    private final Listeners<MailManagerListener> listeners;
    private final Deliveries deliveries;
    private final Supplier<List<String>> recipients;

    MailProvider(String uid, Sender send, Supplier<MailStatus> status, Listeners<MailManagerListener> listeners,
            Deliveries deliveries, Supplier<List<String>> recipients) {
        this.uid = uid;
        this.send = send;
        this.status = status;
        this.listeners = listeners;
        this.deliveries = deliveries;
        this.recipients = recipients;
    }

    @Override
    public void send(String subject, String body) {
        send.send(List.of(), subject, body);
    }

    @Override
    public String sendTo(List<String> to, String subject, String body) {
        return send.send(to == null ? List.of() : to, subject, body);
    }

    @Override
    public Optional<MailDelivery> delivery(String id) {
        return deliveries.get(id);
    }

    @Override
    public List<MailDelivery> deliveries() {
        return deliveries.all();
    }

    @Override
    public List<String> recipients() {
        return recipients.get();
    }

    @Override
    public MailStatus status() {
        return status.get();
    }

    @Override
    public String deviceUid() {
        return uid;
    }

    @Override
    public Connection connect(MailManagerListener listener) {
        return listeners.add(listener);
    }

    @Override
    public String toString() {
        return "MailManagerProvider of " + uid;
    }
}
