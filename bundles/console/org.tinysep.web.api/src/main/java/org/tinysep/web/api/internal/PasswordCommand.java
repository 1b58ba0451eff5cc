package org.tinysep.web.api.internal;

import java.util.Hashtable;
import java.util.List;
import org.apache.felix.service.command.CommandSession;
import org.apache.felix.service.command.Function;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;

/**
 * {@code tinysep:web-password <installer|caregiver> <password>}: sets a console password (its salted hash goes to
 * the state folder; every open session ends). Gogo maps command names to method names, which cannot hold a '-',
 * so the command is a {@link Function} service of its own.
 */
@Component(immediate = true, service = {})
public final class PasswordCommand implements Function {

    private final WebSecurity security;
    private final ServiceRegistration<Function> registration;

    @Activate
    public PasswordCommand(BundleContext context, @Reference WebSecurity security) {
        this.security = security;
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("osgi.command.scope", "tinysep");
        props.put("osgi.command.function", "web-password");
        this.registration = context.registerService(Function.class, this, props);
    }

    @Deactivate
    void deactivate() {
        try {
            registration.unregister();
        } catch (IllegalStateException ignored) {
            // the bundle is stopping
        }
    }

    @Override
    public Object execute(CommandSession session, List<Object> arguments) {
        if (arguments.size() != 2) {
            throw new IllegalArgumentException("usage: web-password <installer|caregiver> <password>");
        }
        Role role = Role.parse(String.valueOf(arguments.get(0))).orElseThrow(() -> new IllegalArgumentException(
                "unknown role '" + arguments.get(0) + "': installer or caregiver"));
        security.passwords().set(role, String.valueOf(arguments.get(1)));
        security.sessions().clear();
        return "web console password of the " + role.id() + " set (salted PBKDF2 hash in "
                + security.passwords().file() + "); open sessions were ended";
    }
}
