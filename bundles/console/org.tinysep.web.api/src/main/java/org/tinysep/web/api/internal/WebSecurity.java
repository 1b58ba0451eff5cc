package org.tinysep.web.api.internal;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.EnumMap;
import java.util.Map;
import java.util.function.Consumer;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.osgi.service.component.annotations.Reference;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.device.support.files.StateFolder;

/**
 * The console's security state, shared by the login filter, the API and the shell command: passwords, sessions,
 * the login rate limit. Wall-clock time (never the platform clock: a simulated day must not end sessions).
 */
@Component(service = WebSecurity.class, configurationPid = WebConfig.PID)
@Designate(ocd = WebConfig.class)
public final class WebSecurity {

    private static final Logger LOG = LoggerFactory.getLogger(WebSecurity.class);
    /** Origin of the console's event-log entries. */
    static final String ORIGIN = "web-console";

    private final PasswordStore passwords;
    private final Sessions sessions;
    private final LoginLimiter limiter;
    private final Consumer<String> problems;
    private final boolean plainHttpOffLoopback;

    @Activate
    public WebSecurity(BundleContext context, WebConfig config, @Reference(name = "eventLog") EventLog log) {
        this(file(context, config), config, Clock.systemUTC(), p -> log.record(EventKind.PROBLEM, ORIGIN, p));
    }

    /** @param problems records a PROBLEM entry in the event log (a flood of failed logins, an unsafe address) */
    WebSecurity(Path file, WebConfig config, Clock clock, Consumer<String> problems) {
        this.problems = problems;
        this.plainHttpOffLoopback = config.allowPlainHttpOffLoopback();
        Map<Role, String> configured = new EnumMap<>(Role.class);
        configured.put(Role.INSTALLER, config.installer_hash());
        configured.put(Role.CAREGIVER, config.caregiver_hash());
        this.passwords = new PasswordStore(file, configured);
        this.sessions = new Sessions(Duration.ofMinutes(Math.max(1, config.sessionIdleMinutes())), clock);
        this.limiter = new LoginLimiter(config.loginMaxFailures(),
                Duration.ofSeconds(Math.max(1, config.loginWindowSeconds())), clock);
        if (!passwords.anySet()) {
            LOG.info("The web console has no password yet: set one in the shell with "
                    + "tinysep:web-password installer <password> (at least {} characters)", PasswordStore.MIN_LENGTH);
        }
    }

    @Deactivate
    void deactivate() {
        sessions.clear();
    }

    public PasswordStore passwords() {
        return passwords;
    }

    public Sessions sessions() {
        return sessions;
    }

    public LoginLimiter limiter() {
        return limiter;
    }

    /** @return whether plain HTTP may be served beyond loopback (configuration allowPlainHttpOffLoopback) */
    public boolean plainHttpOffLoopback() {
        return plainHttpOffLoopback;
    }

    /** Records a security PROBLEM (the message starts with "Security: ") and logs it as a warning. */
    public void problem(String text) {
        LOG.warn("{}", text);
        try {
            problems.accept("Security: " + text);
        } catch (RuntimeException e) { // the event log stopping: the warning above remains
            LOG.debug("Cannot record the security problem", e);
        }
    }

    private static Path file(BundleContext context, WebConfig config) {
        Path dir = StateFolder.resolveOrDataArea(null, context, "web");
        if (!config.passwordFile().isBlank()) {
            return Path.of(config.passwordFile().strip());
        }
        return dir == null ? null : dir.resolve("passwords.properties");
    }
}
