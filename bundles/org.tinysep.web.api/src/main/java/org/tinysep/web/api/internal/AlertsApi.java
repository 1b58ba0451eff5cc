package org.tinysep.web.api.internal;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.tinysep.api.service.InactivityRecognitionProvider;

/**
 * {@code /api/alerts}: open alerts and their acknowledgement. The platform has no alert service yet (another
 * change brings one, with acknowledgement); until it exists this answers {@code alertService: false} with a plain
 * sentence, and Inactivity Recognition's state (its alert, if raised) as the only alert source;
 * {@code POST /api/alerts/{id}/acknowledge} answers 503. This class is the one place to connect that service:
 * {@link #status()} and {@link #acknowledge(String)}; the login filter already lets the caregiver acknowledge.
 */
final class AlertsApi {

    /** The alert service's interface name, looked up by name only: this bundle does not depend on it. */
    static final String ALERT_SERVICE = "org.tinysep.api.service.AlertService";
    static final String NO_SERVICE = "no alert service: the platform has no alert service with acknowledgement yet; "
            + "Inactivity Recognition's own alert is shown, and it ends by itself when activity is seen again";
    private static final Pattern ID = Pattern.compile("[A-Za-z0-9_.:-]{1,100}");

    private final BundleContext context;
    private final PlatformView platform;

    AlertsApi(BundleContext context, PlatformView platform) {
        this.context = context;
        this.platform = platform;
    }

    /** GET /api/alerts */
    Map<String, Object> status() {
        Map<String, Object> out = new LinkedHashMap<>();
        boolean present = serviceRegistered();
        out.put("alertService", false);
        out.put("message", present ? "an alert service is running, but this console does not know it yet: "
                + "update the web console" : NO_SERVICE);
        out.put("alerts", List.of());
        out.put("inactivity", platform.withService(InactivityRecognitionProvider.class, CaregiverApi::inactivity)
                .orElse(null));
        return out;
    }

    /** POST /api/alerts/{id}/acknowledge */
    Map<String, Object> acknowledge(String id) {
        if (!ID.matcher(id).matches()) {
            throw ApiException.badRequest("'" + Strings.shorten(id, 40) + "' is not an alert id");
        }
        throw new ApiException(503, NO_SERVICE);
    }

    private boolean serviceRegistered() {
        try {
            return context.getAllServiceReferences(ALERT_SERVICE, null) != null;
        } catch (InvalidSyntaxException e) {
            return false;
        }
    }
}
