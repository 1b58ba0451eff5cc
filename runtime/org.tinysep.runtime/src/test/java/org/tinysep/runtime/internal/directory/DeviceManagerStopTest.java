package org.tinysep.runtime.internal.directory;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Field;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import org.apache.felix.framework.FrameworkFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceRegistration;
import org.osgi.framework.SynchronousBundleListener;
import org.osgi.framework.launch.Framework;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;

/**
 * Issue 14: the device manager gives every device service back as soon as the framework begins to stop, before any
 * bundle stops, so the drivers' unregistrations do not each scan its use of every device (Felix's linear usage
 * arrays: the stop of 10,000 devices was quadratic). A real Felix framework.
 */
class DeviceManagerStopTest {

    @TempDir
    Path storage;

    @Test
    void everyDeviceServiceIsGivenBackWhenTheFrameworkBeginsToStop() throws Exception {
        Framework fw = new FrameworkFactory().newFramework(Map.of(Constants.FRAMEWORK_STORAGE, storage.toString(),
                Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT));
        fw.start();
        BundleContext context = fw.getBundleContext();
        List<ServiceRegistration<Device>> devices = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            Hashtable<String, Object> props = new Hashtable<>();
            props.put(DeviceProperties.DEVICE_UID, "dev-" + i);
            props.put(DeviceProperties.DEVICE_TYPE, "Fake");
            props.put(DeviceProperties.DRIVER_UID, "drv-1");
            devices.add(context.registerService(Device.class, new FakeDevice("dev-" + i, "Fake", "drv-1", "Fake " + i),
                    props));
        }
        DeviceManager manager = new DeviceManager();
        Field log = DeviceManager.class.getDeclaredField("eventLog");
        log.setAccessible(true);
        log.set(manager, new RecordingEventLog());
        manager.activate(context);
        assertEquals(200, manager.devices().size());
        // issue 29: it keeps each device object but no use of it in the registry (a device's services are singletons)
        assertNull(devices.get(7).getReference().getUsingBundles(), "the manager holds no use of a device service");
        assertEquals("Fake 7", manager.devices().stream().filter(d -> d.uid().equals("dev-7")).findFirst()
                .orElseThrow().device().name(), "and still reaches the device");

        // told after the manager's listener (same bundle, registered later): what is still in use at that moment
        AtomicReference<Bundle[]> inUseWhenStopping = new AtomicReference<>(new Bundle[0]);
        context.addBundleListener((SynchronousBundleListener) e -> {
            if (e.getType() == BundleEvent.STOPPING && e.getBundle().getBundleId() == 0) {
                inUseWhenStopping.set(devices.get(7).getReference().getUsingBundles());
            }
        });
        fw.stop();
        fw.waitForStop(60_000);
        assertNull(inUseWhenStopping.get(), "given back before any bundle stops (was: held until level 4 stopped)");
        assertTrue(manager.released());
        manager.deactivate(); // DS would call it later: harmless
    }
}
