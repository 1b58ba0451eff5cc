package org.tinysep.mqtt.internal;

import java.util.function.Consumer;
import org.slf4j.Logger;

/**
 * What the bridge checks before it connects (docs/mqtt.md, "Who may act"), each finding a PROBLEM in the event log
 * in plain words: a broker login (no login ⇒ the broker lets anyone in ⇒ refused unless {@code allowAnonymous}),
 * the flat's key, and commands that anyone may give.
 */
final class BridgeChecks {

    private BridgeChecks() {
    }

    /** @return false when the bridge must not connect: anonymous without {@code allowAnonymous=true} */
    static boolean loginAllowed(Settings s, Consumer<String> problem, Logger log) {
        if (!s.anonymous()) {
            return true;
        }
        if (!s.allowAnonymous()) {
            String why = "Monitoring reduced: the MQTT bridge of flat " + s.flatId() + " does not connect to "
                    + s.brokerUrl() + ", so this flat's alerts do not reach the care centre: no broker login is "
                    + "configured (username and passwordFile, or a client certificate in keyStore). A broker that lets "
                    + "clients in without a login lets anyone read this flat's alerts and publish to its topics. Set "
                    + "username and passwordFile in configuration org.tinysep.mqtt (or allowAnonymous=true, not "
                    + "recommended).";
            log.warn("{}", why);
            problem.accept(why);
            return false;
        }
        String warn = "The MQTT bridge of flat " + s.flatId() + " connects to " + s.brokerUrl() + " WITHOUT a login "
                + "(allowAnonymous=true): anyone who can reach this broker can read this flat's alerts and publish to "
                + "its topics (fake alerts, commands). Only signed commands are carried out; set username and "
                + "passwordFile in configuration org.tinysep.mqtt to end this.";
        log.warn("{}", warn);
        problem.accept(warn);
        return true;
    }

    /** Reports a missing or open key file, and commands that anyone on the broker may give. */
    static void key(Settings s, FlatKey key, Consumer<String> problem, Logger log) {
        if (key.missing() != null) {
            String why = "Monitoring reduced: the MQTT bridge of flat " + s.flatId() + " has no key (" + key.missing()
                    + "): the care centre's board ignores this flat's alerts, which it cannot tell from fakes, and "
                    + "signed commands (acknowledgements from the care centre) are refused. Put the key the care "
                    + "centre gave for this flat into " + s.keyFile() + " (chmod 600) and restart the bridge.";
            log.warn("{}", why);
            problem.accept(why);
        } else if (key.warning() != null) {
            log.warn("MQTT bridge: {}", key.warning());
            problem.accept("warning: " + key.warning());
        }
        for (String[] k : new String[][] {{"commands.ack", "acknowledge its alerts"},
                {"commands.actuators", "switch its lights, heaters and speakers"}}) {
            CommandPolicy p = k[0].equals("commands.ack") ? s.ackCommands() : s.actuatorCommands();
            if (p == CommandPolicy.UNSIGNED) {
                String warn = "The MQTT bridge of flat " + s.flatId() + " carries out unsigned commands (" + k[0]
                        + "=unsigned): anyone who may publish to its command topics on " + s.brokerUrl() + " can "
                        + k[1] + ".";
                log.warn("{}", warn);
                problem.accept(warn);
            }
        }
    }
}
