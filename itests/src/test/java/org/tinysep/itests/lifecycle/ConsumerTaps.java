package org.tinysep.itests.lifecycle;

import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementProvider;

/**
 * Two listening posts for a {@link DeliveryLedger}: one on every AmICA UDP bus device (what the radio received),
 * one on every AmICA Movement provider (what a movement consumer got). Like any consumer, the movement tap follows
 * providers through the service registry, so it reconnects by itself after an update.
 */
final class ConsumerTaps implements AutoCloseable {

    private final ServiceTracker<BusRadioAmicaProvider, Connection> radio;
    private final ServiceTracker<MovementProvider, Connection> movement;
    private volatile DeliveryLedger ledger = new DeliveryLedger();

    ConsumerTaps(BundleContext context) throws InvalidSyntaxException {
        radio = new ServiceTracker<>(context, FrameworkUtil.createFilter("(&(objectClass="
                + BusRadioAmicaProvider.class.getName() + ")(" + DeviceProperties.DRIVER_NAME + "=BusRadioAmicaUdp))"),
                null) {
            @Override
            public Connection addingService(ServiceReference<BusRadioAmicaProvider> ref) {
                BusRadioAmicaProvider p = context.getService(ref);
                BusRadioAmicaListener tap = (source, payload, at) -> {
                    if (isMotion(payload)) {
                        ledger.radio(source.nodeId(), at);
                    }
                };
                return p.connect(tap);
            }

            @Override
            public void removedService(ServiceReference<BusRadioAmicaProvider> ref, Connection c) {
                c.close();
                context.ungetService(ref);
            }
        };
        movement = new ServiceTracker<>(context, FrameworkUtil.createFilter("(&(objectClass="
                + MovementProvider.class.getName() + ")(" + DeviceProperties.DRIVER_NAME + "=AmicaMovement))"), null) {
            @Override
            public Connection addingService(ServiceReference<MovementProvider> ref) {
                MovementProvider p = context.getService(ref);
                String node = String.valueOf(ref.getProperty(DeviceProperties.NODE_ADDRESS));
                MovementListener tap = (source, event) -> ledger.consumer(node, event.at());
                return p.connect(tap);
            }

            @Override
            public void removedService(ServiceReference<MovementProvider> ref, Connection c) {
                c.close();
                context.ungetService(ref);
            }
        };
        radio.open();
        movement.open();
    }

    /** From now on, record into {@code next}. */
    void record(DeliveryLedger next) {
        ledger = next;
    }

    private static boolean isMotion(byte[] payload) {
        try {
            return AmicaPayloads.decode(payload) instanceof MotionDetection;
        } catch (AmicaProtocolException e) {
            return false;
        }
    }

    @Override
    public void close() {
        movement.close();
        radio.close();
    }
}
