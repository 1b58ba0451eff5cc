package org.tinysep.launcher;

import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;

/**
 * Whether every Declarative Services component configured by a file of {@code etc/} runs with that file's
 * configuration (issue 29: {@link Readiness} checks this instead of waiting for 300 ms of a quiet service registry).
 * Read from SCR's {@code ServiceComponentRuntime} DTOs through reflection (the launcher sees only the framework's
 * packages): FileInstall puts the file's URL in the configuration's {@value #FILENAME}, which SCR hands to the
 * component's properties.
 */
final class ConfiguredComponents {

    static final String SCR = "org.osgi.service.component.runtime.ServiceComponentRuntime";
    static final String FILENAME = "felix.fileinstall.filename";
    /** {@code ComponentConfigurationDTO} states (OSGi DS 1.4). */
    static final int UNSATISFIED_CONFIGURATION = 1;
    static final int UNSATISFIED_REFERENCE = 2;
    static final int SATISFIED = 4;
    static final int ACTIVE = 8;

    /** A component description: its configuration PIDs, whether immediate, its configurations. */
    record Component(List<String> pids, boolean immediate, List<Configuration> configurations) {
    }

    /** One configuration of a component: its state and the {@value #FILENAME} of its properties ("" if none). */
    record Configuration(int state, String file) {
    }

    private ConfiguredComponents() {
    }

    /**
     * @param files      file names in {@code etc/} ({@code <pid>.cfg}, {@code <factoryPid>-<name>.cfg})
     * @param components the components SCR knows
     * @return the files some component is configured by but does not run with yet (a file no component takes, e.g.
     *         Felix HTTP's or FileInstall's own, is never waited for)
     */
    static Set<String> waitingFor(Set<String> files, List<Component> components) {
        Set<String> waiting = new TreeSet<>();
        for (String file : files) {
            String pid = pid(file);
            for (Component c : components) {
                if (c.pids().contains(pid) && c.configurations().stream().noneMatch(k -> runsWith(c, k, file))) {
                    waiting.add(file);
                }
            }
        }
        return waiting;
    }

    /** @return whether {@code k} holds {@code file}'s configuration and is done with it (not still activating) */
    private static boolean runsWith(Component c, Configuration k, String file) {
        boolean settled = k.state() == ACTIVE || k.state() == UNSATISFIED_REFERENCE || k.state() > ACTIVE // failed
                || (k.state() == SATISFIED && !c.immediate());
        return settled && k.file().endsWith("/" + file);
    }

    /** @return the PID (or factory PID) of {@code <pid>.cfg} or {@code <factoryPid>-<name>.cfg}, as FileInstall reads it */
    static String pid(String file) {
        String name = file.endsWith(".cfg") ? file.substring(0, file.length() - 4) : file;
        int dash = name.indexOf('-');
        return dash > 0 ? name.substring(0, dash) : name;
    }

    /** @return the components SCR knows, or empty when there is no SCR (or its DTOs cannot be read) */
    static Optional<List<Component>> read(BundleContext context) {
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(SCR, null);
            if (refs == null) {
                return Optional.empty();
            }
            Object scr = context.getService(refs[0]);
            try {
                Class<?> type = refs[0].getBundle().loadClass(SCR);
                Class<?> descriptionType = refs[0].getBundle()
                        .loadClass("org.osgi.service.component.runtime.dto.ComponentDescriptionDTO");
                List<Component> out = new ArrayList<>();
                for (Object d : (Collection<?>) type.getMethod("getComponentDescriptionDTOs", org.osgi.framework.Bundle[].class)
                        .invoke(scr, (Object) new org.osgi.framework.Bundle[0])) {
                    if ("ignore".equals(field(d, "configurationPolicy"))
                            || !(Boolean) type.getMethod("isComponentEnabled", descriptionType).invoke(scr, d)) {
                        continue; // takes no configuration, or is switched off: never runs with a file
                    }
                    List<Configuration> configurations = new ArrayList<>();
                    for (Object c : (Collection<?>) type.getMethod("getComponentConfigurationDTOs", descriptionType)
                            .invoke(scr, d)) {
                        Object file = ((Map<?, ?>) field(c, "properties")).get(FILENAME);
                        configurations.add(new Configuration((Integer) field(c, "state"), file == null ? "" : file.toString()));
                    }
                    out.add(new Component(List.of((String[]) field(d, "configurationPid")), (Boolean) field(d, "immediate"),
                            configurations));
                }
                return Optional.of(out);
            } finally {
                context.ungetService(refs[0]);
            }
        } catch (ReflectiveOperationException | InvalidSyntaxException | RuntimeException e) {
            return Optional.empty();
        }
    }

    private static Object field(Object dto, String name) throws ReflectiveOperationException {
        Field f = dto.getClass().getField(name);
        return f.get(dto);
    }
}
