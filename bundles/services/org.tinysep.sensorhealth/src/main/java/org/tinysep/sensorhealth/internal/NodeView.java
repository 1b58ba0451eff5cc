package org.tinysep.sensorhealth.internal;

import java.util.Objects;
import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.osgi.util.tracker.ServiceTrackerCustomizer;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.device.support.lifecycle.ServiceUse;
import org.tinysep.sensorhealth.internal.Placements.OnNode;

/**
 * Feeds the {@link NodeIndex} from the service registry: the bus devices' {@link NodeHealthSource}s and the devices
 * on nodes (which name and place a node), as they come, change and go. Nothing here reads the whole registry again.
 */
final class NodeView implements AutoCloseable {

    private final ServiceTracker<NodeHealthSource, NodeHealthSource> sources;
    private final ServiceTracker<Device, Device> devices;

    NodeView(BundleContext context, NodeIndex index) {
        this.sources = new ServiceTracker<>(context, NodeHealthSource.class, new ServiceTrackerCustomizer<>() {
            @Override
            public NodeHealthSource addingService(ServiceReference<NodeHealthSource> ref) {
                NodeHealthSource s = ServiceUse.take(context, ref); // no use left per node
                if (s != null) {
                    index.sourceAdded(uid(ref), String.valueOf(ref.getProperty(DeviceProperties.NODE_ADDRESS)),
                            (String) ref.getProperty(DeviceProperties.ROOM), s);
                }
                return s;
            }

            @Override
            public void modifiedService(ServiceReference<NodeHealthSource> ref, NodeHealthSource s) {
                index.sourceModified(uid(ref), (String) ref.getProperty(DeviceProperties.ROOM));
            }

            @Override
            public void removedService(ServiceReference<NodeHealthSource> ref, NodeHealthSource s) {
                index.sourceRemoved(uid(ref), s);
                ServiceUse.release(context, ref);
            }
        });
        try {
            this.devices = new ServiceTracker<>(context, FrameworkUtil.createFilter("(&(objectClass="
                    + Device.class.getName() + ")(" + DeviceProperties.NODE_ADDRESS + "=*))"),
                    new ServiceTrackerCustomizer<Device, Device>() {
                        @Override
                        public Device addingService(ServiceReference<Device> ref) {
                            Device d = ServiceUse.take(context, ref);
                            if (d != null) {
                                index.deviceChanged(onNode(ref, d));
                            }
                            return d;
                        }

                        @Override
                        public void modifiedService(ServiceReference<Device> ref, Device d) {
                            index.deviceChanged(onNode(ref, d));
                        }

                        @Override
                        public void removedService(ServiceReference<Device> ref, Device d) {
                            index.deviceRemoved(uid(ref));
                            ServiceUse.release(context, ref);
                        }
                    });
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        sources.open();
        devices.open();
    }

    private static String uid(ServiceReference<?> ref) {
        return String.valueOf(ref.getProperty(DeviceProperties.DEVICE_UID));
    }

    private static OnNode onNode(ServiceReference<Device> ref, Device d) {
        return new OnNode(uid(ref), String.valueOf(ref.getProperty(DeviceProperties.NODE_ADDRESS)),
                (String) ref.getProperty(DeviceProperties.ROOM), d::name,
                bus -> d.connections().stream().anyMatch(c -> Objects.equals(c.providerDeviceUid(), bus)));
    }

    @Override
    public void close() {
        sources.close();
        devices.close();
    }
}
