package org.tinysep.device.support.sensor;

import java.util.function.BiFunction;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.NodeTypeDriver;

/**
 * A sensor bundle's driver: one device per bus device (of type {@code P}) whose {@code tinysep.node.type} contains
 * the sensor's node type; nodes of other types are ignored (thesis Fig 3.3). The subclass is the DS component:
 * {@code @Component(service = {}, immediate = true)} and a constructor; its bundle's {@code bnd.bnd} says
 * {@code -dsannotations-options: inherit} so that the activate and deactivate methods of {@link NodeTypeDriver}
 * count.
 *
 * @param <P> the bus device interface, {@code BusRadioAmicaProvider} or {@code BusRadioSunSpotProvider}
 */
public abstract class SensorDriver<P> extends NodeTypeDriver<P> {

    /** @param devices makes the device of one bus device, e.g. {@code AmicaDoorDevice::new} */
    protected SensorDriver(String name, Class<P> bus, String nodeType,
            BiFunction<DriverContext, P, AbstractDevice> devices) {
        super(name, bus, nodeType, devices);
    }
}
