package org.tinysep.mqtt.board.loadtest;

import org.eclipse.paho.mqttv5.client.IMqttMessageListener;
import org.eclipse.paho.mqttv5.client.IMqttToken;
import org.eclipse.paho.mqttv5.client.MqttCallback;
import org.eclipse.paho.mqttv5.client.MqttDisconnectResponse;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.eclipse.paho.mqttv5.common.packet.MqttProperties;

/**
 * A test client's Paho v5 callback, written once for the board's tests (the broker test's flat and the load test's
 * simulated flats): hands every arriving message to one listener and ignores the other events, which these clients
 * learn from their tokens or do not need. A client-wide callback, not per-subscription listeners: Paho's
 * per-subscription listeners recurse (docs). Public only so that the tests in {@code board.internal} can use it.
 */
public final class MessageCallback implements MqttCallback {

    private final IMqttMessageListener listener;

    public MessageCallback(IMqttMessageListener listener) {
        this.listener = listener;
    }

    @Override
    public void messageArrived(String topic, MqttMessage message) throws Exception {
        listener.messageArrived(topic, message);
    }

    @Override
    public void disconnected(MqttDisconnectResponse response) {
    }

    @Override
    public void mqttErrorOccurred(MqttException exception) {
    }

    @Override
    public void deliveryComplete(IMqttToken token) {
    }

    @Override
    public void connectComplete(boolean reconnect, String serverURI) {
    }

    @Override
    public void authPacketArrived(int reasonCode, MqttProperties properties) {
    }
}
