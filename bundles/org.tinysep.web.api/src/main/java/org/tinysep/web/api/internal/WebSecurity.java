package org.tinysep.web.api.internal;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.EnumMap;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.device.support.StateFolder;

/**
 * The console's security state, shared by the login filter, the API and the shell command: passwords, sessions,
 * the login rate limit. Wall-clock time (never the platform clock: a simulated day must not end sessions).
 */
@Component(service = WebSecurity.class, configurationPid = WebConfig.PID)
@Designate(ocd = WebConfig.class)
public final class WebSecurity {

    private static final Logger LOG = LoggerFactory.getLogger(WebSecurity.class);

    private final PasswordStore passwords;
    private final Sessions sessions;
    private final LoginLimiter limiter;

    @Activate
    public WebSecurity(BundleContext context, WebConfig config) {
        this(file(context, config), config, Clock.systemUTC());
    }

    WebSecurity(Path file, WebConfig config, Clock clock) {
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

    private static Path file(BundleContext context, WebConfig config) {
        Path dir = StateFolder.resolveOrDataArea(null, context, "web");
        if (!config.passwordFile().isBlank()) {
            return Path.of(config.passwordFile().strip());
        }
        return dir == null ? null : dir.resolve("passwords.properties");
    }
}
