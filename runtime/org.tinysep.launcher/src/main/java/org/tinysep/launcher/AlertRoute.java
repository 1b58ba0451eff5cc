package org.tinysep.launcher;

import java.time.Duration;
import java.util.Optional;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;

/**
 * The banner's line on where alerts go: read from the Mail Manager's Driver service properties
 * {@code tinysep.mail.delivery} ({@code none}, {@code invalid}, {@code smtp}) and {@code tinysep.mail.summary}
 * (one plain sentence), so that a gateway whose alerts reach nobody says so where the user looks first.
 */
final class AlertRoute {

    static final String DELIVERY = "tinysep.mail.delivery";
    static final String SUMMARY = "tinysep.mail.summary";
    static final String MAILED = "alerts are mailed";

    private AlertRoute() {
    }

    /**
     * @param context the framework's bundle context
     * @param wait    how long to wait for the Mail Manager (an application the drivers list starts)
     * @return the line for the banner
     */
    static String line(BundleContext context, Duration wait) throws InterruptedException {
        long end = System.nanoTime() + wait.toNanos();
        ServiceReference<?> mail = find(context);
        while (mail == null && System.nanoTime() < end) {
            Thread.sleep(50);
            mail = find(context);
        }
        if (mail == null) {
            return "WARNING: alerts are only written to the log: the Mail Manager is not running "
                    + "(tinysep:drivers shows why)";
        }
        return describe(String.valueOf(mail.getProperty(DELIVERY)), String.valueOf(mail.getProperty(SUMMARY)));
    }

    /** @return {@code Alerts: …} when alerts are mailed and nothing failed, else {@code WARNING: …} */
    static String describe(String delivery, String summary) {
        boolean fine = "smtp".equals(delivery) && summary.startsWith(MAILED);
        return (fine ? "Alerts: " : "WARNING: alerts: ") + summary;
    }

    private static ServiceReference<?> find(BundleContext context) {
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(null, "(" + DELIVERY + "=*)");
            // all references: the system bundle cannot see the Driver interface, so the other call would hide it
            return refs == null || refs.length == 0 ? null : refs[0];
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
