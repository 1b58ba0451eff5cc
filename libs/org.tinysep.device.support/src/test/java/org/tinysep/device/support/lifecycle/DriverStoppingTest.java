package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Proxy;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;

/**
 * A driver whose bundle is stopping must not treat its closing trackers' "provider removed" callbacks as the
 * providers going away (found by the removal integration test: every device of a stopped driver was logged as
 * having "lost its vital connections"). {@link AbstractDriver#providerGone} asks {@link DriverContext#stopping()}.
 */
class DriverStoppingTest {

    private static BundleContext contextOfBundleIn(int state) {
        Bundle bundle = (Bundle) Proxy.newProxyInstance(Bundle.class.getClassLoader(), new Class<?>[] {Bundle.class},
                (proxy, method, args) -> {
                    if (method.getName().equals("getState")) {
                        return state;
                    }
                    throw new UnsupportedOperationException(method.getName());
                });
        return (BundleContext) Proxy.newProxyInstance(BundleContext.class.getClassLoader(),
                new Class<?>[] {BundleContext.class}, (proxy, method, args) -> {
                    if (method.getName().equals("getBundle") && (args == null || args.length == 0)) {
                        if (state == 0) {
                            throw new IllegalStateException("invalid bundle context");
                        }
                        return bundle;
                    }
                    throw new UnsupportedOperationException(method.getName());
                });
    }

    @Test
    void aRunningOrStartingBundleIsNotStopping() {
        assertFalse(DriverContext.stopping(contextOfBundleIn(Bundle.ACTIVE)));
        assertFalse(DriverContext.stopping(contextOfBundleIn(Bundle.STARTING)));
    }

    @Test
    void aStoppingOrStoppedBundleOrAnInvalidContextIsStopping() {
        assertTrue(DriverContext.stopping(contextOfBundleIn(Bundle.STOPPING)));
        assertTrue(DriverContext.stopping(contextOfBundleIn(Bundle.RESOLVED)));
        assertTrue(DriverContext.stopping(contextOfBundleIn(Bundle.UNINSTALLED)));
        assertTrue(DriverContext.stopping(contextOfBundleIn(0)), "an invalidated context throws");
    }

    @Test
    void withoutAFrameworkNothingIsStopping() {
        assertFalse(DriverContext.stopping(null));
    }
}
