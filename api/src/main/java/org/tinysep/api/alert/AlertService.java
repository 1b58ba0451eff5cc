package org.tinysep.api.alert;

import java.util.List;
import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Connection;

/**
 * Owns the platform's alerts: keeps them across restarts, notifies the contact list, repeats
 * and escalates an alert nobody acknowledges, and sends an "all clear" when its cause ends. Every step is an
 * event-log entry in plain words. The shell ({@code tinysep:alerts}, {@code tinysep:ack}), the web console and an
 * MQTT bridge all go through this interface.
 */
@ProviderType
public interface AlertService {

    /**
     * Raises an alert (or returns the open one of the same source and time) and notifies the first contact at once.
     * Never blocks on the network.
     */
    Alert raise(AlertRequest request);

    /**
     * Acknowledges an open alert: it is no longer repeated or escalated.
     *
     * @param id the alert's id
     * @param by who takes care of it, in words ("Anna (phone)", "shell", a web user); must not be blank
     * @return the acknowledged alert
     * @throws IllegalArgumentException for an unknown id or a blank {@code by}, in plain words
     * @throws IllegalStateException    when the alert is not open any more (says since when and why)
     */
    Alert acknowledge(String id, String by);

    /**
     * The cause of the source's alerts ended by itself (the person is active again): open ones are cleared and
     * an "all clear" goes to everyone told of them; acknowledged ones are cleared quietly.
     *
     * @param why in plain words, e.g. "movement in Kitchen at 14:40"
     * @return the alerts cleared
     */
    List<Alert> clear(String source, String why);

    /** @return the open alerts, oldest first */
    List<Alert> open();

    /** @return the newest {@code max} alerts, open or closed, oldest first */
    List<Alert> recent(int max);

    Optional<Alert> alert(String id);

    /** Subscribes to every change; the connection closes when the service goes away. */
    Connection connect(AlertListener listener);
}
