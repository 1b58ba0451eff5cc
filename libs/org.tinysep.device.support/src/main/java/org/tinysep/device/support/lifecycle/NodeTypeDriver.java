package org.tinysep.device.support.lifecycle;

import java.util.function.BiFunction;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Deactivate;
import org.tinysep.api.device.DeviceProperties;

/**
 * The driver of a device bundle that abstracts nodes of one type: one device per bus device (of type {@code P})
 * whose {@code tinysep.node.type} contains that node type; nodes of other types are ignored (thesis Fig 3.3). Sensors
 * use it as {@code sensor.SensorDriver}, AmICA actuators directly. The subclass is the DS component:
 * {@code @Component(service = {}, immediate = true)} and a constructor; its bundle's {@code bnd.bnd} says
 * {@code -dsannotations-options: inherit} so that the activate and deactivate methods here count.
 *
 * @param <P> the bus device interface, {@code BusRadioAmicaProvider} or {@code BusRadioSunSpotProvider}
 */
public abstract class NodeTypeDriver<P> extends ProviderDeviceDriver<P> {

    private final BiFunction<DriverContext, P, AbstractDevice> devices;

    /** @param devices makes the device of one bus device, e.g. {@code AmicaDoorDevice::new} */
    protected NodeTypeDriver(String name, Class<P> bus, String nodeType,
            BiFunction<DriverContext, P, AbstractDevice> devices) {
        super(name, bus, "(" + DeviceProperties.NODE_TYPE + "=" + nodeType + ")");
        this.devices = devices;
    }

    @Activate
    protected void activate(BundleContext bundleContext) {
        open(bundleContext);
    }

    @Deactivate
    protected void deactivate() {
        close();
    }

    @Override
    protected final AbstractDevice createDevice(P bus) {
        return devices.apply(context(), bus);
    }
}
