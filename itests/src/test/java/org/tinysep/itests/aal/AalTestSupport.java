package org.tinysep.itests.aal;

import static org.junit.Assert.assertArrayEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.itests.TinySepTestSupport;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * AAL service tests: the Time Controller in EXTERNAL (virtual, lock-step) mode on a free port, House Information on
 * a fresh temp file, simulated AmICA nodes over UDP placed in rooms with {@code tinysep:set <uid> room <room>}.
 */
abstract class AalTestSupport extends TinySepTestSupport {

    /** Inactivity Recognition reading days in UTC, for tests that check times of day ({@code HH:mm} in mails). */
    static final Map<String, String> INACTIVITY_UTC = Map.of("timeZone", "UTC");

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        configs.put("org.tinysep.timecontroller", org.tinysep.itests.TestSyncKey.timeConfig("EXTERNAL"));
        try {
            configs.put("org.tinysep.houseinformation", Map.of("file",
                    Files.createTempDirectory("tinysep-aal-house-").resolve("house.xml").toString()));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return configs;
    }

    /** @return a lock-step synchroniser on the Time Controller's port */
    SyncPeer sync() throws IOException {
        SyncPeer sync = new SyncPeer(syncPort());
        try {
            return sync.hello();
        } catch (IOException | RuntimeException | Error e) {
            sync.close();
            throw e;
        }
    }

    /**
     * Points the Mail Manager at a test SMTP server (no TLS, short timeouts and retries, a fresh spool folder) with
     * one recipient, and waits until it is configured: idle and mailing that recipient.
     *
     * @return the Mail Manager
     */
    MailManagerProvider mailTo(SmtpSink sink, String recipient) throws IOException {
        configure("org.tinysep.mailmanager", Map.of("host", "127.0.0.1", "port", Integer.toString(sink.port()),
                "security", "NONE", "from", "tinysep@home.test", "recipients", recipient,
                "connectTimeoutSeconds", "2", "retryInitialSeconds", "1", "retryMaxSeconds", "2",
                "spoolDir", Files.createTempDirectory("tinysep-aal-spool").toString()));
        MailManagerProvider mail = awaitService(MailManagerProvider.class, null, TIMEOUT);
        await(TIMEOUT, () -> mail.status() == MailStatus.IDLE && mail.recipients().equals(List.of(recipient)),
                "the Mail Manager configured");
        return mail;
    }

    /** @return a whole second a day ahead of the platform clock: the start of a test's virtual time */
    Instant tomorrow() {
        return awaitService(TimeControllerProvider.class, null, TIMEOUT).now().truncatedTo(ChronoUnit.SECONDS)
                .plusSeconds(86_400);
    }

    /**
     * Adds a room unless the house has one of that name already (the framework of each test method may start on
     * the same house file).
     */
    void room(String name, String type) {
        HouseInformationProvider house = awaitService(HouseInformationProvider.class, null, TIMEOUT);
        if (house.rooms().stream().noneMatch(r -> r.name().equals(name))) {
            shell("tinysep:room-add \"" + name + "\" \"" + type + "\"");
        }
    }

    /** Waits for the node's device of that type and places it in the room (by name) through the shell. */
    Device place(AmicaNode node, String deviceType, String roomName) throws IOException {
        node.keepAlive();
        Device d = awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=" + deviceType + ")("
                + DeviceProperties.NODE_ADDRESS + "=" + node.id() + "))", TIMEOUT);
        // all its services registered (it connects to its bus device only afterwards): see DeviceServices' race
        await(TIMEOUT, () -> !d.connections().isEmpty(), d.name() + " fully registered");
        String set = "tinysep:set " + d.uid() + " room \"" + roomName + "\"";
        // the device manager's inventory may lag the Device service by a moment: retry only that failure
        await(TIMEOUT, () -> {
            try {
                shell(set);
                return true;
            } catch (AssertionError e) {
                if (!String.valueOf(e.getMessage()).contains("no device matches")) {
                    throw e;
                }
                return false;
            }
        }, "the device manager to know " + d.uid());
        await(TIMEOUT, () -> hasRoom(d.uid()), d.name() + " placed in " + roomName);
        return d;
    }

    /**
     * {@link #place} in a room named like its type ({@code Bathroom}, {@code Kitchen}, …), adding the room first
     * unless the house has it: the usual set-up of one sensor per room.
     */
    Device placeIn(AmicaNode node, String deviceType, String room) throws IOException {
        room(room, room);
        return place(node, deviceType, room);
    }

    private boolean hasRoom(String deviceUid) {
        try {
            ServiceReference<?>[] refs = context.getServiceReferences((String) null,
                    "(&(" + DeviceProperties.DEVICE_UID + "=" + deviceUid + ")(" + DeviceProperties.ROOM + "=*))");
            return refs != null;
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    static String parameter(Device device, String key) {
        return device.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError(device + " has no parameter " + key));
    }

    /** Reads the next command the platform sends to the node and compares it byte by byte. */
    static void expectCommand(AmicaNode node, int... payload) throws Exception {
        byte[] expected = new byte[payload.length];
        for (int i = 0; i < payload.length; i++) {
            expected[i] = (byte) payload[i];
        }
        assertArrayEquals("command to " + node.id(), expected, node.receivePayload());
    }
}
