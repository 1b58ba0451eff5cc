package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeSet;
import java.util.function.Function;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.Device;
import org.tinysep.device.support.lifecycle.ServiceUse;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;

/**
 * Read access to the platform's {@link Driver} and {@link Device} services and their service properties, straight
 * from the service registry (the same services the {@code tinysep:devices} command lists); every call sees the
 * registry as it is now.
 */
public final class PlatformView {

    /** A device with the service properties that say where it is and what it provides. */
    public record DeviceRef(Device device, String uid, String driverName, String room, String nodeAddress,
            List<String> nodeTypes, List<String> provides) {
    }

    private final BundleContext context;

    public PlatformView(BundleContext context) {
        this.context = context;
    }

    /** @return every device, ordered by name */
    public List<DeviceRef> devices() {
        List<DeviceRef> out = new ArrayList<>();
        for (ServiceReference<Device> ref : refs(Device.class, null)) {
            Device d = ServiceUse.take(context, ref); // no use left per device in the registry
            if (d != null) {
                try {
                    String uid = String.valueOf(ref.getProperty(DeviceProperties.DEVICE_UID));
                    out.add(new DeviceRef(d, uid, text(ref, DeviceProperties.DRIVER_NAME), text(ref, DeviceProperties.ROOM),
                            text(ref, DeviceProperties.NODE_ADDRESS), strings(ref.getProperty(DeviceProperties.NODE_TYPE)),
                            provides(uid)));
                } finally {
                    ServiceUse.release(context, ref); // DS components stay registered; calls after unget are still answered
                }
            }
        }
        out.sort((a, b) -> Safely.get(a.device()::name, a.uid()).compareToIgnoreCase(Safely.get(b.device()::name, b.uid())));
        return out;
    }

    /** @return the device with this UID (exactly) */
    public Optional<DeviceRef> device(String uid) {
        return devices().stream().filter(d -> d.uid().equals(uid)).findFirst();
    }

    /** @return every driver with its name */
    public List<Driver> drivers() {
        List<Driver> out = new ArrayList<>();
        for (ServiceReference<Driver> ref : refs(Driver.class, null)) {
            Driver d = context.getService(ref);
            if (d != null) {
                out.add(d);
                context.ungetService(ref);
            }
        }
        out.sort((a, b) -> Safely.get(a::name, "").compareToIgnoreCase(Safely.get(b::name, "")));
        return out;
    }

    /** @return the drivers registered by {@code bundle} */
    public List<Driver> drivers(org.osgi.framework.Bundle bundle) {
        List<Driver> out = new ArrayList<>();
        for (ServiceReference<Driver> ref : refs(Driver.class, null)) {
            if (bundle.equals(ref.getBundle())) {
                Driver d = context.getService(ref);
                if (d != null) {
                    out.add(d);
                    context.ungetService(ref);
                }
            }
        }
        return out;
    }

    /** @return UID → name of every device and driver, for showing log origins */
    public Map<String, String> names() {
        Map<String, String> names = new LinkedHashMap<>();
        for (Driver d : drivers()) {
            names.put(Safely.get(d::uid, ""), Safely.get(d::name, ""));
        }
        for (DeviceRef d : devices()) {
            names.put(d.uid(), Safely.get(() -> d.device().name(), d.uid()));
        }
        return names;
    }

    /** @return the UIDs of the devices providing {@code providerInterface} (e.g. MovementProvider), with their room */
    public Map<String, String> providersWithRoom(Class<?> providerInterface) {
        Map<String, String> out = new LinkedHashMap<>();
        for (ServiceReference<?> ref : refs(providerInterface, "(" + DeviceProperties.ROOM + "=*)")) {
            out.put(text(ref, DeviceProperties.DEVICE_UID), text(ref, DeviceProperties.ROOM));
        }
        return out;
    }

    /** @return the service of {@code type} (the highest ranked), applied to {@code use} */
    public <S, R> Optional<R> withService(Class<S> type, Function<S, R> use) {
        ServiceReference<S> ref = context.getServiceReference(type);
        if (ref == null) {
            return Optional.empty();
        }
        S service = context.getService(ref);
        if (service == null) {
            return Optional.empty();
        }
        try {
            return Optional.ofNullable(use.apply(service));
        } finally {
            context.ungetService(ref);
        }
    }

    private List<String> provides(String uid) {
        TreeSet<String> names = new TreeSet<>();
        for (ServiceReference<?> ref : refs(null, "(" + DeviceProperties.DEVICE_UID + "=" + escape(uid) + ")")) {
            for (String cls : strings(ref.getProperty(Constants.OBJECTCLASS))) {
                String simple = cls.substring(cls.lastIndexOf('.') + 1);
                if (!simple.equals("Device") && !simple.equals("Driver")) {
                    names.add(simple);
                }
            }
        }
        return List.copyOf(names);
    }

    @SuppressWarnings("unchecked")
    private <S> List<ServiceReference<S>> refs(Class<S> type, String filter) {
        try {
            ServiceReference<?>[] found = context.getAllServiceReferences(type == null ? null : type.getName(), filter);
            if (found == null) {
                return List.of();
            }
            List<ServiceReference<S>> out = new ArrayList<>();
            for (ServiceReference<?> r : found) {
                out.add((ServiceReference<S>) r);
            }
            return out;
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException("bad filter " + filter, e);
        }
    }

    private static String text(ServiceReference<?> ref, String key) {
        Object v = ref.getProperty(key);
        return v == null ? "" : v.toString();
    }

    private static List<String> strings(Object value) {
        if (value instanceof String[] a) {
            return Arrays.asList(a);
        }
        if (value instanceof java.util.Collection<?> c) {
            return c.stream().map(String::valueOf).toList();
        }
        return value == null ? List.of() : List.of(value.toString());
    }

    /** Escapes an LDAP filter value. */
    static String escape(String value) {
        StringBuilder sb = new StringBuilder();
        for (char c : value.toCharArray()) {
            if (c == '\\' || c == '*' || c == '(' || c == ')') {
                sb.append('\\');
            }
            sb.append(c);
        }
        return sb.toString();
    }
}
