package org.tinysep.runtime.internal.shell;

import java.lang.reflect.InvocationTargetException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.function.Supplier;
import org.apache.felix.service.command.Descriptor;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;

/**
 * {@code help}: every shell command, read from the registered command services' {@code osgi.command.scope} and
 * {@code osgi.command.function} properties, so the list cannot go stale. Gogo's own {@code felix:help} leaves out
 * every command that is not a Java method of its service (the {@code Function} services: {@code tinysep:rooms}, the
 * {@code room-*} commands, {@code web-password}). Gogo resolves a plain {@code help} by its scope's key and runs the
 * highest ranked service of that key, so this one is registered as {@code felix:help} ranked above Gogo's;
 * {@code help <command>} is handed to Gogo's.
 */
// name: the component name (and PID) it had before the runtime was split into packages
@Component(name = "org.tinysep.runtime.internal.HelpCommand",
        service = HelpCommand.class, property = {
    "osgi.command.scope=felix",
    "osgi.command.function=help",
    "service.ranking:Integer=1"
})
public final class HelpCommand {

    /** Explains one command (in the platform: Gogo's own help). */
    interface Explainer {
        Object explain(String command) throws Exception;
    }

    private final Supplier<Collection<Map<String, Object>>> commandServices;
    private final Explainer explainer;

    @Activate
    public HelpCommand(BundleContext context) {
        this.commandServices = () -> properties(context);
        this.explainer = command -> gogoHelp(context, command);
    }

    HelpCommand(Supplier<Collection<Map<String, Object>>> commandServices, Explainer explainer) {
        this.commandServices = commandServices;
        this.explainer = explainer;
    }

    @Descriptor("lists every shell command (scope:name); help <command> explains one")
    public String help() {
        return String.join("\n", names(commandServices.get()));
    }

    @Descriptor("explains one command (Gogo's felix:help)")
    public Object help(@Descriptor("the command, e.g. tinysep:devices") String command)
            throws Exception {
        if (!command.matches("[\\w.:-]+")) {
            throw new IllegalArgumentException("not a command name: '" + command + "'; usage: help [command]");
        }
        return explainer.explain(command);
    }

    /** @return every {@code scope:function} the services declare, sorted, each once */
    static List<String> names(Collection<Map<String, Object>> services) {
        TreeSet<String> out = new TreeSet<>();
        for (Map<String, Object> p : services) {
            Object scope = p.get("osgi.command.scope");
            Object functions = p.get("osgi.command.function");
            List<Object> each = functions instanceof Object[] a ? List.of(a)
                    : functions instanceof Collection<?> c ? new ArrayList<>(c)
                    : functions == null ? List.of() : List.of(functions);
            for (Object f : each) {
                out.add(scope + ":" + f);
            }
        }
        return new ArrayList<>(out);
    }

    /** Runs Gogo's {@code help <command>} (org.apache.felix.gogo.command), the other {@code felix:help}. */
    private Object gogoHelp(BundleContext context, String command) throws Exception {
        ServiceReference<?>[] refs = context.getServiceReferences((String) null,
                "(&(osgi.command.scope=felix)(osgi.command.function=help))");
        for (ServiceReference<?> r : refs == null ? new ServiceReference<?>[0] : refs) {
            Object gogo = context.getService(r);
            try {
                if (gogo != null && gogo != this) {
                    return gogo.getClass().getMethod("help", String.class).invoke(gogo, command); // Basic's
                }
            } catch (NoSuchMethodException e) {
                // not Gogo's: try the next
            } catch (InvocationTargetException e) {
                throw e.getCause() instanceof Exception x ? x : e;
            } finally {
                context.ungetService(r);
            }
        }
        throw new IllegalStateException("cannot explain " + command + ": Gogo's help (bundle"
                + " org.apache.felix.gogo.command) is not running; the list of commands is: help");
    }

    private static Collection<Map<String, Object>> properties(BundleContext context) {
        List<Map<String, Object>> out = new ArrayList<>();
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(null, "(osgi.command.scope=*)");
            for (ServiceReference<?> r : refs == null ? new ServiceReference<?>[0] : refs) {
                Object functions = r.getProperty("osgi.command.function");
                if (functions != null) {
                    out.add(Map.of("osgi.command.scope", String.valueOf(r.getProperty("osgi.command.scope")),
                            "osgi.command.function", functions));
                }
            }
        } catch (InvalidSyntaxException | IllegalStateException e) {
            throw new IllegalStateException("cannot list the commands: " + e.getMessage());
        }
        return out;
    }
}
