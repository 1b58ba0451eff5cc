package org.tinysep.houseinformation.internal;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
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
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.device.support.logs.Reporter;

/**
 * Places devices in rooms by their node address (the wire protocols carry no rooms): tracks the Device services
 * with {@code tinysep.node.address} and sets the {@code room} parameter of an unplaced one a rule names. The work
 * runs on this component's own thread, never inside the service event (registrations cascade on radio threads).
 */
@Component(service = {}, immediate = true, configurationPid = RoomPlacer.PID)
@Designate(ocd = PlacementConfig.class)
public final class RoomPlacer {

    static final String PID = "org.tinysep.houseinformation.placement";
    static final String ORIGIN = "RoomPlacement";
    static final int ATTEMPTS = 10;
    static final long RETRY_MS = 200;
    /** Placements within this time of the first one of a burst are summed up in one console line. */
    static final long SUMMARY_DELAY_MS = 2000;
    private static final Logger LOG = LoggerFactory.getLogger(RoomPlacer.class);

    private final ScheduledExecutorService executor = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "tinysep-room-placement");
        t.setDaemon(true);
        return t;
    });
    /** Rules whose room was unknown, reported once per configuration. */
    private final Set<PlacementRules.Rule> reported = ConcurrentHashMap.newKeySet();
    private volatile PlacementRules rules = PlacementRules.parse("");
    private BundleContext context;
    private Reporter reporter;
    private ServiceTracker<Device, ServiceReference<Device>> devices;
    private ServiceTracker<HouseInformationProvider, HouseInformationProvider> house;
    /** Devices placed since the last summary line, and their rooms; used on the executor's thread only. */
    private final PlacementSummary burst = new PlacementSummary();

    @Activate
    void activate(BundleContext bundleContext, PlacementConfig config) throws InvalidSyntaxException {
        context = bundleContext;
        reporter = Reporter.tracking(bundleContext);
        house = new ServiceTracker<>(bundleContext, HouseInformationProvider.class, null);
        house.open();
        configure(config);
        devices = new ServiceTracker<>(bundleContext, bundleContext.createFilter("(&(objectClass="
                + Device.class.getName() + ")(" + DeviceProperties.NODE_ADDRESS + "=*))"), null) {
            @Override
            public ServiceReference<Device> addingService(ServiceReference<Device> ref) {
                submit(ref); // appeared, or its address appeared
                return ref;
            }
        };
        devices.open();
    }

    @Modified
    void modified(PlacementConfig config) {
        configure(config);
        ServiceReference<Device>[] present = devices.getServiceReferences();
        if (present != null) {
            for (ServiceReference<Device> ref : present) {
                submit(ref);
            }
        }
    }

    @Deactivate
    void deactivate() {
        devices.close();
        executor.shutdownNow();
        house.close();
        reporter.close();
    }

    private void configure(PlacementConfig config) {
        PlacementRules parsed = PlacementRules.parse(config.placements());
        for (String error : parsed.errors()) {
            LOG.warn("{}", error);
            reporter.event(EventKind.PROBLEM, ORIGIN, error);
        }
        reported.clear();
        rules = parsed;
        LOG.info("Room placement: {} rule(s)", parsed.size());
    }

    private void submit(ServiceReference<Device> ref) {
        if (ref.getProperty(DeviceProperties.ROOM) == null) {
            schedule(ref, 1, 0);
        }
    }

    private void schedule(ServiceReference<Device> ref, int attempt, long delayMs) {
        try {
            executor.schedule(() -> place(ref, attempt), delayMs, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException stopping) {
            LOG.debug("Room placement stopping; {} not placed", ref);
        }
    }

    private void place(ServiceReference<Device> ref, int attempt) {
        PlacementRules current = rules;
        if (ref.getBundle() == null || ref.getProperty(DeviceProperties.ROOM) != null) {
            return; // gone, or already placed (by the user or an earlier attempt): never overridden
        }
        PlacementRules.Rule rule = current.ruleFor(ref.getProperty(DeviceProperties.NODE_ADDRESS)).orElse(null);
        if (rule == null) {
            return;
        }
        String uid = String.valueOf(ref.getProperty(DeviceProperties.DEVICE_UID));
        Placement outcome = Placement.apply(context, ref, rule, house.getService());
        switch (outcome.result()) {
            case PLACED -> {
                LOG.debug("Placed device {} (node {}) in room {}", uid, rule.address(), outcome.detail());
                if (burst.add(outcome.detail())) {
                    executor.schedule(() -> LOG.info("{}", burst.takeLine()), SUMMARY_DELAY_MS, TimeUnit.MILLISECONDS);
                }
            }
            case UNKNOWN_ROOM -> {
                if (reported.add(rule)) {
                    reporter.event(EventKind.PROBLEM, ORIGIN, "placement rule '" + rule + "': "
                            + outcome.detail() + "; devices of node " + rule.address() + " are not placed");
                }
            }
            case NOT_YET -> {
                if (attempt < ATTEMPTS) {
                    schedule(ref, attempt + 1, RETRY_MS);
                } else {
                    reporter.event(EventKind.PROBLEM, ORIGIN, "could not place device " + uid + " (node "
                            + rule.address() + ") in room '" + rule.room() + "' after " + ATTEMPTS + " attempts: "
                            + outcome.detail());
                }
            }
            case SKIPPED -> LOG.debug("Device {} not placed: {}", uid, outcome.detail());
            default -> throw new IllegalStateException(outcome.toString());
        }
    }
}
