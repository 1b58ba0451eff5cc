package org.tinysep.mailmanager.internal;

import java.util.function.BiConsumer;
import java.util.function.Supplier;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.device.support.Listeners;

/**
 * The MailManagerProvider side of the device: a separate object because {@code MailManagerProvider.status()} and
 * {@code Device.status()} differ in type.
 */
final class MailProvider implements MailManagerProvider {

    private final String uid;
    private final BiConsumer<String, String> send;
    private final Supplier<MailStatus> status;
    private final Listeners<MailManagerListener> listeners;

    MailProvider(String uid, BiConsumer<String, String> send, Supplier<MailStatus> status,
            Listeners<MailManagerListener> listeners) {
        this.uid = uid;
        this.send = send;
        this.status = status;
        this.listeners = listeners;
    }

    @Override
    public void send(String subject, String body) {
        send.accept(subject, body);
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
