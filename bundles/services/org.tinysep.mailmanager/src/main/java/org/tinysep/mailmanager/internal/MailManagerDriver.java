package org.tinysep.mailmanager.internal;

import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.files.StateFolder;
import org.tinysep.device.support.lifecycle.AbstractDriver;

/**
 * Mail Manager driver (thesis 4.4.3.3): like House Information it creates its one device at once, with no
 * prerequisites. A configuration change is applied to the running device, so connected consumers keep it.
 */
@Component(service = {}, immediate = true, configurationPid = MailManagerDriver.PID)
@Designate(ocd = MailManagerConfig.class)
public final class MailManagerDriver extends AbstractDriver {

    public static final String PID = "org.tinysep.mailmanager";
    public static final String NAME = "MailManager";
    /** Driver service property: {@code none} (no SMTP host), {@code invalid} (refused configuration) or {@code smtp}. */
    public static final String DELIVERY_PROPERTY = "tinysep.mail.delivery";
    /** Driver service property: where alerts go and what is wrong, in one plain sentence (for the banner). */
    public static final String SUMMARY_PROPERTY = "tinysep.mail.summary";

    private static final Logger LOG = LoggerFactory.getLogger(MailManagerDriver.class);

    private String tinysepVar;
    private String tinysepHome;
    private MailManagerDevice device;
    private volatile MailHealth health;

    public MailManagerDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, Map<String, Object> properties) {
        tinysepVar = bundleContext.getProperty(StateFolder.VAR);
        tinysepHome = bundleContext.getProperty(StateFolder.HOME);
        Parsed p = parse(properties);
        health = new MailHealth(p.settings, p.problem, null, "", null);
        start(bundleContext, serviceProperties(health));
        parseProblem(p);
        device = addDevice(new MailManagerDevice(context(), p.settings, p.problem, new SmtpTransport(),
                Clock.systemUTC(), this::healthChanged));
    }

    @Modified
    void modified(Map<String, Object> properties) {
        Parsed p = parse(properties);
        parseProblem(p);
        device.reconfigure(p.settings, p.problem);
    }

    /** Where alerts go, in the driver's figures ({@code tinysep:drivers}). */
    @Override
    public List<Parameter> parameters() {
        MailHealth h = health;
        return List.of(Parameter.readOnly("delivery", h.delivery(), "none (no SMTP host: alerts only in the log), "
                + "invalid (bad configuration: alerts only in the log) or smtp"),
                Parameter.readOnly("alerts", h.summary(), "where alerts go and what is wrong, in plain words"));
    }

    /** Called on the mail thread: the service properties follow, so the launcher's banner can show them. */
    private synchronized void healthChanged(MailHealth next) {
        MailHealth before = health;
        health = next;
        if (!next.delivery().equals(before.delivery()) || !next.summary().equals(before.summary())) {
            driverProperties(serviceProperties(next));
        }
    }

    private static Map<String, Object> serviceProperties(MailHealth h) {
        return Map.of(DELIVERY_PROPERTY, h.delivery(), SUMMARY_PROPERTY, h.summary());
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
            LOG.info("{} configured: {}", NAME, s.configured() ? s.redacted() : MailHealth.NO_HOST);
            return new Parsed(s, null);
        } catch (IllegalArgumentException e) {
            MailSettings fallback = MailSettings.parse(Map.of("spoolDir", spoolDirOf(properties)), tinysepVar, tinysepHome);
            return new Parsed(fallback, e.getMessage());
        }
    }

    private void parseProblem(Parsed p) {
        if (p.problem != null) {
            String problem = "configuration " + PID + " refused: " + p.problem;
            LOG.warn("{}; alerts are only written to the log until it is fixed", problem);
            context().event(EventKind.PROBLEM, problem);
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
