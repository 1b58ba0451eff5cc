package org.tinysep.drivers.internal;

import org.apache.felix.service.command.Converter;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;

/**
 * Lets the plain Felix shell commands that take bundles ({@code uninstall}, {@code update}, {@code stop},
 * {@code refresh}, …) accept a bundle id or symbolic name when the interactive Gogo shell bundle — which normally
 * brings this conversion — is not installed (daemon mode, commands run through the {@code CommandProcessor}).
 */
@Component(service = Converter.class)
public final class BundleConverter implements Converter {

    private final BundleContext context;

    @Activate
    public BundleConverter(BundleContext context) {
        this.context = context;
    }

    @Override
    public Object convert(Class<?> desiredType, Object in) {
        if (desiredType != Bundle.class || in == null) {
            return null;
        }
        String text = in.toString().strip();
        if (text.matches("\\d{1,18}")) {
            return context.getBundle(Long.parseLong(text));
        }
        for (Bundle b : context.getBundles()) {
            if (text.equals(b.getSymbolicName())) {
                return b;
            }
        }
        return null;
    }

    @Override
    public CharSequence format(Object target, int level, Converter escape) {
        return null; // formatting stays with Gogo's defaults
    }
}
