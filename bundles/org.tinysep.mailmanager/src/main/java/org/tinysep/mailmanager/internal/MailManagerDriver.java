package org.tinysep.mailmanager.internal;

import java.nio.file.Path;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.AbstractDriver;
import org.tinysep.device.support.StateFolder;

/**
 * Mail Manager driver (thesis 4.4.3.3): like House Information it creates its one device at once, with no
 * prerequisites. A configuration change is applied to the running device, so connected consumers keep it.
 */
@Component(service = {}, immediate = true, configurationPid = MailManagerDriver.PID)
@Designate(ocd = MailManagerConfig.class)
public final class MailManagerDriver extends AbstractDriver {

    public static final String PID = "org.tinysep.mailmanager";
    public static final String NAME = "MailManager";

    private static final Logger LOG = LoggerFactory.getLogger(MailManagerDriver.class);

    private String tinysepVar;
    private String tinysepHome;
    private MailManagerDevice device;

    public MailManagerDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, Map<String, Object> properties) {
        tinysepVar = bundleContext.getProperty(StateFolder.VAR);
        tinysepHome = bundleContext.getProperty(StateFolder.HOME);
        start(bundleContext);
        Parsed p = parse(properties);
        device = addDevice(new MailManagerDevice(context(), p.settings, p.problem, new SmtpTransport()));
    }

    @Modified
    void modified(Map<String, Object> properties) {
        Parsed p = parse(properties);
        device.reconfigure(p.settings, p.problem);
    }

    @Deactivate
    void deactivate() {
        stop();
    }

    private record Parsed(MailSettings settings, String problem) {
    }

    private Parsed parse(Map<String, Object> properties) {
        try {
            MailSettings s = MailSettings.parse(properties, tinysepVar, tinysepHome);
            LOG.info("{} configured: {}", NAME, s.redacted());
            return new Parsed(s, null);
        } catch (IllegalArgumentException e) {
            String problem = "configuration " + PID + " refused: " + e.getMessage();
            LOG.warn("{}; mail is written to the log until it is fixed", problem);
            context().event(EventKind.PROBLEM, problem);
            MailSettings fallback = MailSettings.parse(Map.of("spoolDir", spoolDirOf(properties)), tinysepVar, tinysepHome);
            return new Parsed(fallback, e.getMessage());
        }
    }

    /** The spool folder of a refused configuration, if that part of it is usable, so queued mail is still found. */
    private String spoolDirOf(Map<String, Object> properties) {
        Object dir = properties.get("spoolDir");
        try {
            return dir == null ? "" : Path.of(dir.toString().strip()).toString();
        } catch (RuntimeException e) {
            return "";
        }
    }
}
