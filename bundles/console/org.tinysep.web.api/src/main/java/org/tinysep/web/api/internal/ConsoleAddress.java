package org.tinysep.web.api.internal;

import java.util.Arrays;
import java.util.List;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Says where the console is: logs the HTTP service's address ({@code osgi.http.endpoint} of its runtime service)
 * whenever it appears or changes, with how to set the first password when none is set; an address beyond
 * loopback without TLS is a PROBLEM "Security: ..." ({@link PlainHttpRule}).
 */
@Component(immediate = true, service = {})
public final class ConsoleAddress {

    private static final Logger LOG = LoggerFactory.getLogger(ConsoleAddress.class);
    private static final String RUNTIME = "org.osgi.service.servlet.runtime.HttpServiceRuntime";

    private final ServiceTracker<Object, Object> tracker;
    private volatile String announced = "";

    @Activate
    public ConsoleAddress(BundleContext context, @Reference WebSecurity security) throws InvalidSyntaxException {
        tracker = new ServiceTracker<>(context, context.createFilter("(objectClass=" + RUNTIME + ")"), null) {
            @Override
            public Object addingService(ServiceReference<Object> ref) {
                announce(ref, security);
                return ref;
            }

            @Override
            public void modifiedService(ServiceReference<Object> ref, Object service) {
                announce(ref, security);
            }
        };
        tracker.open();
    }

    @Deactivate
    void deactivate() {
        tracker.close();
    }

    private void announce(ServiceReference<?> ref, WebSecurity security) {
        Object endpoint = ref.getProperty("osgi.http.endpoint");
        String where = endpoint instanceof String[] a ? String.join(" ", Arrays.asList(a)) : String.valueOf(endpoint);
        if (endpoint == null || where.isBlank() || where.equals(announced)) {
            return; // the runtime's properties change often (change count); say the address once
        }
        announced = where;
        List<String> endpoints = endpoint instanceof String[] a ? List.of(a) : List.of(where);
        PlainHttpRule.problem(endpoints, security.plainHttpOffLoopback()).ifPresent(security::problem);
        LOG.info("Web console: {}{}", where, security.passwords().anySet() ? ""
                : " (no password yet: tinysep:web-password installer <password>)");
    }
}
