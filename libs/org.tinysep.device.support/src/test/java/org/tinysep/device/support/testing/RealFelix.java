package org.tinysep.device.support.testing;

import java.lang.reflect.Field;
import java.nio.file.Path;
import java.util.Map;
import org.apache.felix.framework.FrameworkFactory;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.launch.Framework;

/**
 * A real Felix framework (system bundle only) for tests that count what its service registry holds: started in a
 * test's storage folder, stopped by {@link #close()}. {@link #usesInRegistry()} reads Felix's per-bundle use arrays,
 * which every new use searches and copies and every unregistration scans: the work per device that must not grow
 * with the number of devices (issue 29, item 4).
 */
public final class RealFelix implements AutoCloseable {

    private final Framework fw;

    public RealFelix(Path storage) throws Exception {
        fw = new FrameworkFactory().newFramework(Map.of(Constants.FRAMEWORK_STORAGE, storage.toString(),
                Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT));
        fw.start();
    }

    public BundleContext context() {
        return fw.getBundleContext();
    }

    /** @return the service uses Felix holds for all bundles (count 0 included): the entries its registry scans */
    public int usesInRegistry() throws ReflectiveOperationException {
        Field registryField = fw.getClass().getDeclaredField("m_registry");
        registryField.setAccessible(true);
        Object registry = registryField.get(fw);
        Field inUse = registry.getClass().getDeclaredField("m_inUseMap");
        inUse.setAccessible(true);
        int total = 0;
        for (Object usages : ((Map<?, ?>) inUse.get(registry)).values()) {
            total += ((Object[]) usages).length;
        }
        return total;
    }

    @Override
    public void close() throws Exception {
        fw.stop();
        fw.waitForStop(30_000);
    }
}
