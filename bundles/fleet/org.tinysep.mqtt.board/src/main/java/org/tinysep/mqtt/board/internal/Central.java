package org.tinysep.mqtt.board.internal;

import java.nio.file.Path;
import java.time.Clock;
import java.time.ZoneId;
import java.util.function.Consumer;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.tinysep.mqtt.board.internal.Liveness.Rules;

/**
 * One running board: the state ({@link Board}), its intake and, when a broker is configured, its MQTT link. Idle
 * (no link, an empty board that says why) while {@code brokerUrl} is empty.
 */
final class Central implements AutoCloseable {

    private final Board board;
    private final Intake intake;
    private final BoardClient client;
    private final Rules rules;
    private final Clock clock;
    private final String defaultBy;

    private final String refusal;
    private final FlatKeys keys;

    /**
     * @param var     the state folder ({@code tinysep.var}): default places of the password file and the flats' keys
     * @param problem records a PROBLEM in the event log (plain words)
     */
    Central(BoardConfig c, Clock clock, Intake.Applied applied, Path var, Consumer<String> problem)
            throws MqttException {
        this.clock = clock;
        BoardLogin login = c.brokerUrl().isBlank() ? null : BoardLogin.of(c, var, problem);
        refusal = login == null ? null : login.refusal();
        this.keys = login == null || refusal != null ? null : FlatKeys.read(c.flatKeyDir().isBlank()
                ? var.resolve("secrets").resolve("flats") : Path.of(c.flatKeyDir().strip()), c.flats(), problem);
        this.board = new Board(c.topicPrefix(), Math.max(1, c.maxFlats()), keys);
        this.intake = new Intake(board, clock, applied);
        this.rules = new Rules(Math.max(1, c.missedHeartbeats()), Math.max(1, c.summaryHours()), c.lowBatteryPercent(),
                c.timeZone().isBlank() ? ZoneId.systemDefault() : ZoneId.of(c.timeZone()));
        this.defaultBy = c.acknowledgedBy().isBlank() ? "care centre" : c.acknowledgedBy();
        if (login == null || refusal != null) {
            client = null;
        } else {
            client = new BoardClient(new BoardClient.Settings(c.brokerUrl(), c.clientId(), login.username(),
                    login.password(), c.trustStore(), c.trustStorePassword().toCharArray(), c.topicPrefix()),
                    intake, clock.withZone(rules.zone())); // its zone: the times of its link words
            client.start();
        }
    }

    String json() {
        String link = refusal != null ? refusal : client == null
                ? "idle: no broker configured (set brokerUrl in pid org.tinysep.mqtt.board)" : client.link();
        return BoardView.json(board, rules, clock.instant(), link, client != null && client.connected());
    }

    /**
     * Sends the acknowledgement of a flat's open alert.
     *
     * @return what happened, in plain words
     * @throws IllegalArgumentException unknown flat or alert; IllegalStateException not open or no broker link
     */
    String acknowledge(String flatId, String alertId, String by) throws MqttException {
        String who = by == null || by.isBlank() ? defaultBy : Payloads.cut(by.strip(), 80);
        Flat flat = board.find(flatId).orElseThrow(() -> new IllegalArgumentException("the board knows no flat " + flatId));
        Flat.Entry e = flat.snapshot().alerts().stream().filter(a -> a.alert().id().equals(alertId)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("flat " + flatId + " has no alert " + alertId + " on the board"));
        if (!e.alert().state().equals("OPEN")) {
            throw new IllegalStateException("alert " + alertId + " of flat " + flatId + " is " + e.alert().state()
                    + ", not open: nothing to acknowledge");
        }
        if (client == null || !client.connected()) {
            throw new IllegalStateException("the board is not connected to the broker: the acknowledgement cannot travel to flat " + flatId);
        }
        byte[] key = keys == null ? null : keys.of(flatId);
        if (key == null) {
            throw new IllegalStateException("the board has no key for flat " + flatId + ": the flat would refuse an "
                    + "unsigned acknowledgement");
        }
        client.acknowledge(flatId, alertId, who, key);
        flat.ackSent(alertId, who, clock.instant());
        return "acknowledgement of alert " + alertId + " sent to flat " + flatId + " by " + who
                + "; the board shows it as acknowledged once the flat confirms";
    }

    Board board() {
        return board;
    }

    @Override
    public void close() {
        if (client != null) {
            client.close();
        }
        intake.close();
    }
}
