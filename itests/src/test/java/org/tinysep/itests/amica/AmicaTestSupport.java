package org.tinysep.itests.amica;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.IntFunction;
import java.util.function.Supplier;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.api.actuator.PercentActuator;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Percent;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.TinySepTestSupport;

/**
 * Helpers for the AmICA hardware-abstraction tests: simulated nodes on the UDP bus radio, the devices and
 * providers of one node address, their parameters.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class) // both inherited by the test classes
public abstract class AmicaTestSupport extends TinySepTestSupport {

    /**
     * Sends the node's keep-alive and waits for its abstraction: the Device service of {@code deviceType} and the
     * provider of {@code type}, which must carry the node's own type {@code nodeType} only.
     *
     * @return the provider
     */
    protected <P> P announce(AmicaNode node, String deviceType, Class<P> type, String nodeType) throws Exception {
        node.keepAlive();
        device(deviceType, node.id());
        P provider = provider(type, node.id());
        assertEquals(List.of(nodeType), providerNodeTypes(type, node.id()));
        return provider;
    }

    /** Waits for the provider service of that interface at that node address. */
    protected <P> P provider(Class<P> type, String node) {
        return awaitService(type, "(" + DeviceProperties.NODE_ADDRESS + "=" + node + ")", TIMEOUT);
    }

    /** @return the node types published on the provider service of that interface at that node address */
    protected List<String> providerNodeTypes(Class<?> type, String node) {
        provider(type, node);
        ServiceReference<?> ref = references(type.getName(), node).get(0);
        return List.of((String[]) ref.getProperty(DeviceProperties.NODE_TYPE));
    }

    /** Waits for the Device service of that device type at that node address. */
    protected Device device(String deviceType, String node) {
        return awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=" + deviceType + ")("
                + DeviceProperties.NODE_ADDRESS + "=" + node + "))", TIMEOUT);
    }

    /** @return the types of every device registered at that node address, sorted */
    protected Set<String> deviceTypesAt(String node) {
        Set<String> types = new TreeSet<>();
        for (ServiceReference<?> ref : references(Device.class.getName(), node)) {
            types.add((String) ref.getProperty(DeviceProperties.DEVICE_TYPE));
        }
        return types;
    }

    /** @return the current value of one of the device's parameters */
    protected static String parameter(Device device, String key) {
        return device.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError(device + " has no parameter " + key));
    }

    /** Polls until {@code actual} equals {@code expected}; on timeout fails showing both. */
    protected <T> void awaitEquals(String what, T expected, Supplier<T> actual) {
        try {
            await(TIMEOUT, () -> expected.equals(actual.get()), what);
        } catch (AssertionError timeout) {
            assertEquals(what, expected, actual.get());
            throw timeout;
        }
    }

    /**
     * The scenario of the percent actuators (dimmable light, heater, speaker), written once: node {@code 1.address} of
     * {@code type} announces itself; its status reports reach listeners as changes (a repeated one is not); the typed
     * setter puts {@code 5 code 0 A} on the node's socket and the value stays, {@code pending} meanwhile, until the
     * node's next status confirms it; {@code tinysep:set uid key 70} does the same.
     *
     * @param device  the device type, e.g. {@code "AmicaHeater"}
     * @param control makes the node's status and command payload, e.g. {@code HeaterControl::new}
     * @param connect connects a listener to the provider that accepts each value heard
     */
    protected <P extends PercentActuator> void assertPercentActuator(AmicaNodeType type, int address, String device,
            Class<P> provider, IntFunction<AmicaPayload> control, String key, int code,
            BiConsumer<P, Consumer<Percent>> connect) throws Exception {
        try (AmicaNode node = node(1, address, type)) {
            P actuator = announce(node, device, provider, type.typeName());
            Device abstraction = device(device, node.id());
            List<Percent> heard = new CopyOnWriteArrayList<>();
            connect.accept(actuator, heard::add);

            node.send(control.apply(10));
            node.send(control.apply(10)); // repeated every 10 s by the node: not a change
            node.send(control.apply(25));
            awaitEquals("status reports", List.of(Percent.of(10), Percent.of(25)), () -> List.copyOf(heard));

            actuator.setLevel(Percent.of(40));
            expectCommand(node, 5, code, 0, 40);
            assertEquals("unchanged before the node confirms", Optional.of(Percent.of(25)), actuator.level());
            assertEquals("40%", parameter(abstraction, "pending"));
            node.send(control.apply(40));
            awaitEquals("confirmed", List.of(Percent.of(10), Percent.of(25), Percent.of(40)), () -> List.copyOf(heard));
            assertEquals(Optional.of(Percent.of(40)), actuator.level());
            assertEquals("", parameter(abstraction, "pending"));

            shell("tinysep:set " + abstraction.uid() + " " + key + " 70");
            expectCommand(node, 5, code, 0, 70);
            assertEquals("70%", parameter(abstraction, "pending"));
            node.send(control.apply(70));
            awaitEquals(key + " parameter", "70%", () -> parameter(abstraction, key));
        }
    }

    /** Reads the next command the platform sends to the node and compares it byte by byte. */
    protected static void expectCommand(AmicaNode node, int... payload) throws Exception {
        byte[] expected = new byte[payload.length];
        for (int i = 0; i < payload.length; i++) {
            expected[i] = (byte) payload[i];
        }
        assertArrayEquals("command to " + node.id(), expected, node.receivePayload());
    }

    private List<ServiceReference<?>> references(String objectClass, String node) {
        try {
            ServiceReference<?>[] refs = context.getServiceReferences(objectClass,
                    "(" + DeviceProperties.NODE_ADDRESS + "=" + node + ")");
            return refs == null ? List.of() : List.of(refs);
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
