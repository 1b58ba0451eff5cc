package org.tinysep.sunspot.person.internal;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.metatype.annotations.Designate;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.sensor.person.PersonNodeProvider;

/**
 * Names the wearers of person nodes from the configuration (pid {@code org.tinysep.sunspot.person}, key
 * {@code persons}), as House Information's placement names rooms: a person node whose {@code person} parameter is
 * empty when it appears (or when the configuration changes) gets the configured name through
 * {@link Device#setParameter}, so it is kept in the backup like a name the user set; a name already set is never
 * overridden. The work runs on the component's own thread, never inside the service event.
 */
@Component(service = {}, immediate = true, configurationPid = PersonNames.PID)
@Designate(ocd = PersonNamesConfig.class)
public final class PersonNames {

    static final String PID = "org.tinysep.sunspot.person";
    private static final Logger LOG = LoggerFactory.getLogger(PersonNames.class);

    private final ExecutorService executor = Executors.newSingleThreadExecutor(r -> new Thread(r, "person-names"));
    private final BundleContext context;
    private final ServiceTracker<PersonNodeProvider, ServiceReference<PersonNodeProvider>> nodes;
    private volatile PersonRules rules;

    @Activate
    public PersonNames(BundleContext context, PersonNamesConfig config) {
        this.context = context;
        configure(config);
        nodes = new ServiceTracker<>(context, PersonNodeProvider.class, null) {
            @Override
            public ServiceReference<PersonNodeProvider> addingService(ServiceReference<PersonNodeProvider> ref) {
                executor.execute(() -> name(ref));
                return ref;
            }
        };
        nodes.open();
    }

    @Modified
    void modified(PersonNamesConfig config) {
        configure(config);
        ServiceReference<PersonNodeProvider>[] present = nodes.getServiceReferences();
        if (present != null) {
            for (ServiceReference<PersonNodeProvider> ref : present) {
                executor.execute(() -> name(ref));
            }
        }
    }

    private void configure(PersonNamesConfig config) {
        rules = PersonRules.parse(config.persons());
        rules.problems().forEach(p -> LOG.warn("Sun SPOT Person: {}", p));
    }

    @Deactivate
    void deactivate() {
        nodes.close();
        executor.shutdownNow();
    }

    private void name(ServiceReference<PersonNodeProvider> ref) {
        Object address = ref.getProperty(DeviceProperties.NODE_ADDRESS);
        Object uid = ref.getProperty(DeviceProperties.DEVICE_UID);
        String name = address == null ? null : rules.nameOf(address.toString()).orElse(null);
        if (name == null || uid == null) {
            return;
        }
        PersonNodeProvider node = context.getService(ref);
        if (node == null) {
            return;
        }
        try {
            if (node.person().isPresent()) {
                return; // set by the user (or restored from the backup): theirs wins
            }
            if (node instanceof Device d) {
                d.setParameter(SunSpotPersonDevice.PERSON, name);
                LOG.info("Person node {} is worn by {} (configuration {}, persons)", address, name, PID);
            }
        } catch (RuntimeException e) {
            LOG.warn("Person node {}: the wearer {} could not be set: {}", address, name, e.toString());
        } finally {
            context.ungetService(ref);
        }
    }
}
