package org.tinysep.mqtt.internal;

import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;

/**
 * The bridge as a device ({@code tinysep:devices}, web console): its status says whether the broker is reachable
 * (and why not, in plain words), its parameters show the outbox and the command counters. Configuration changes
 * replace the running {@link Bridge}.
 */
final class BridgeDevice extends WholeFlatDevice {

    private static final Logger LOG = LoggerFactory.getLogger(BridgeDevice.class);

    private volatile Settings settings;
    private volatile Figures figures = Figures.IDLE;
    private Bridge bridge;

    BridgeDevice(DriverContext context, Settings settings, String configProblem) {
        super(context, Uids.of(context.driverName(), "device"), context.driverName(), "MQTT bridge");
        this.settings = settings;
        startBridge(configProblem);
    }

    synchronized void reconfigure(Settings next, String configProblem) {
        stopBridge();
        settings = next;
        figures = Figures.IDLE;
        startBridge(configProblem);
    }

    private synchronized void startBridge(String configProblem) {
        if (configProblem != null) {
            status(DeviceStatus.State.ERROR, "configuration refused: " + configProblem);
            return;
        }
        if (!settings.configured()) {
            status(DeviceStatus.State.UNKNOWN, "idle: no brokerUrl configured (configuration org.tinysep.mqtt)");
            return;
        }
        if (!settings.username().isEmpty()) {
            String open = Secrets.openToOthers(settings.passwordFile());
            if (open != null) {
                event("warning: " + open);
                problem("warning: " + open);
            }
        }
        if (!BridgeChecks.loginAllowed(settings, this::problem, LOG)) {
            status(DeviceStatus.State.ERROR, "not connected: no broker login is configured (username and passwordFile, "
                    + "or keyStore) and allowAnonymous is not true");
            return;
        }
        FlatKey key = FlatKey.read(settings.keyFile());
        BridgeChecks.key(settings, key, this::problem, LOG);
        bridge = new Bridge(context.bundleContext(), settings, context::now, this::status, f -> figures = f, key,
                this::problem);
        bridge.start();
    }

    private void problem(String message) {
        context.event(EventKind.PROBLEM, message);
    }

    private synchronized void stopBridge() {
        if (bridge != null) {
            bridge.stop();
            bridge = null;
        }
    }

    @Override
    protected List<Parameter> moreParameters() {
        Settings s = settings;
        Figures f = figures;
        return List.of(
                Parameter.readOnly("broker", s.configured() ? s.redacted() : "none",
                        "the broker, flat id and topic prefix (configuration org.tinysep.mqtt)"),
                Parameter.readOnly("link", f.link(), "the connection to the broker, in words"),
                Parameter.readOnly("waitingAlerts", f.waitingAlerts(),
                        "alert messages kept on disk until the broker acknowledges them"),
                Parameter.readOnly("waitingState", f.waitingState(), "state topics with a newer value not yet sent"),
                Parameter.readOnly("delivered", f.delivered(), "messages the broker acknowledged since the start"),
                Parameter.readOnly("devices", f.devices(), "devices published"),
                Parameter.readOnly("acceptedCommands", f.acceptedCommands(), "commands carried out"),
                Parameter.readOnly("rejectedCommands", f.rejectedCommands(),
                        "commands refused; each refusal is explained on command/result"),
                Parameter.readOnly("refusedCommandsUnauthorised", f.refusedUnauthorised(),
                        "commands refused because unsigned, badly signed, stale, replayed or switched off "
                        + "(commands.ack, commands.actuators); also counted in rejectedCommands"),
                Parameter.readOnly("droppedResults", f.droppedResults(),
                        "command results dropped because more than 1000 waited for the broker"));
    }

    @Override
    protected void onDispose() {
        stopBridge();
    }

    @Override
    protected boolean backedUp(String key) {
        return false;
    }
}
