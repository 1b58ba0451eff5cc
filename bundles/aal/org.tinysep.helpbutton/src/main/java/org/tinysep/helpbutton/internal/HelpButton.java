package org.tinysep.helpbutton.internal;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.sensor.person.ButtonEvent;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.device.support.time.PlatformTicker;

/**
 * The help button (README): listens to every person node's switches and hands help calls to the alert service.
 * The platform ticker (the Time Controller's time when one runs) finds a switch still held; button events carry
 * their frame's arrival.
 */
@Component(service = {}, configurationPid = "org.tinysep.helpbutton", immediate = true)
@Designate(ocd = HelpButtonConfig.class)
public final class HelpButton implements HelpCalls.Desk {

    static final String ORIGIN = "HelpButton";
    private static final Logger LOG = LoggerFactory.getLogger(HelpButton.class);

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile AlertService alerts;
    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile EventLog eventLog;

    private final HelpCalls calls = new HelpCalls(this, this::event);
    private final Map<String, Connection> connections = new ConcurrentHashMap<>();
    private volatile PlatformTicker ticker;

    @Activate
    void activate(BundleContext context, HelpButtonConfig config) {
        configure(config);
        ticker = PlatformTicker.whenDue(context, "tinysep-helpbutton", calls::tick);
        calls.whenDue(ticker::wake);
    }

    @Modified
    void configure(HelpButtonConfig config) {
        try {
            calls.settings(HelpSettings.parse(config));
        } catch (IllegalArgumentException e) {
            calls.settings(HelpSettings.DEFAULTS);
            problem("bad configuration of org.tinysep.helpbutton (" + e.getMessage() + "): using the defaults, "
                    + "hold 1 s, cancel within 10 s, either switch");
        }
        PlatformTicker t = ticker;
        if (t != null) {
            t.wakeNext(); // a shorter hold: a switch held now may be a help call already
        }
    }

    @Deactivate
    void deactivate() {
        if (ticker != null) {
            ticker.close();
        }
        connections.values().forEach(Connection::close);
        connections.clear();
    }

    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    void bindPersonNode(PersonNodeProvider node, Map<String, Object> properties) {
        Object address = properties.get(DeviceProperties.NODE_ADDRESS);
        HelpCalls.Node n = new HelpCalls.Node(node.deviceUid(), address == null ? node.deviceUid()
                : address.toString(), node::person);
        Connection c = node.connect(new PersonNodeListener() {
            @Override
            public void buttonChanged(PersonNodeProvider source, ButtonEvent event) {
                calls.button(n, event);
            }
        });
        Connection old = connections.put(node.deviceUid(), c);
        if (old != null) {
            old.close();
        }
    }

    void unbindPersonNode(PersonNodeProvider node) {
        Connection c = connections.remove(node.deviceUid());
        if (c != null) {
            c.close();
        }
        calls.forget(node.deviceUid());
    }

    @Override
    public Optional<Alert> raise(AlertRequest request) {
        AlertService a = alerts;
        if (a == null) {
            LOG.error("No alert service: the help call '{}' reached nobody", request.subject());
            return Optional.empty();
        }
        return Optional.of(a.raise(request));
    }

    @Override
    public Optional<Integer> clear(String source, String why) {
        AlertService a = alerts;
        return a == null ? Optional.empty() : Optional.of(a.clear(source, why).size());
    }

    private void event(String words) {
        LOG.info("{}", words);
        EventLog log = eventLog;
        if (log != null) {
            log.record(EventKind.DEVICE_EVENT, ORIGIN, words);
        }
    }

    private void problem(String words) {
        LOG.warn("{}", words);
        EventLog log = eventLog;
        if (log != null) {
            log.record(EventKind.PROBLEM, ORIGIN, words);
        }
    }
}
