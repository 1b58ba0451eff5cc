package org.tinysep.web.api.internal;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.service.InactivityRecognitionProvider;

/**
 * {@code /api/alerts}: the alert service's open alerts ({@code org.tinysep.alerts}) and their acknowledgement, the
 * same service the shell's {@code tinysep:alerts} and {@code tinysep:ack} use. Without that service running this
 * answers {@code alertService: false} with a plain sentence and Inactivity Recognition's state (its alert, if
 * raised) as the only alert source; {@code POST /api/alerts/{id}/acknowledge} then answers 503.
 */
final class AlertsApi {

    static final String NO_SERVICE = "no alert service: the alert service (bundle org.tinysep.alerts) is not "
            + "running, so alerts cannot be acknowledged here; Inactivity Recognition's own alert is shown, and it "
            + "ends by itself when activity is seen again";
    private static final Pattern ID = Pattern.compile("[A-Za-z0-9_.:-]{1,100}");

    private final PlatformView platform;

    AlertsApi(PlatformView platform) {
        this.platform = platform;
    }

    /** GET /api/alerts */
    Map<String, Object> status() {
        Optional<List<Alert>> open = platform.withService(AlertService.class, AlertService::open);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("alertService", open.isPresent());
        out.put("message", open.isPresent() ? (open.get().isEmpty() ? "No open alert." : "Open alerts:")
                : NO_SERVICE);
        out.put("alerts", open.orElse(List.of()).stream().map(AlertsApi::json).toList());
        out.put("inactivity", platform.withService(InactivityRecognitionProvider.class, r -> CaregiverApi.inactivity(r, platform))
                .orElse(null));
        return out;
    }

    /** POST /api/alerts/{id}/acknowledge, by the logged-in role ("caregiver (web console)") */
    Map<String, Object> acknowledge(String id, String role) {
        if (!ID.matcher(id).matches()) {
            throw ApiException.badRequest("'" + Strings.shorten(id, 40) + "' is not an alert id");
        }
        String by = role + " (web console)";
        return platform.withService(AlertService.class, s -> {
            if (s.alert(id).isEmpty()) {
                throw ApiException.notFound("no alert " + id);
            }
            try {
                return json(s.acknowledge(id, by));
            } catch (IllegalStateException e) { // closed meanwhile: says since when and why
                throw new ApiException(409, e.getMessage());
            } catch (IllegalArgumentException e) {
                throw ApiException.badRequest(e.getMessage());
            }
        }).orElseThrow(() -> new ApiException(503, NO_SERVICE));
    }

    /**
     * One alert: {@code kindWords} ({@code AlertKind.words()}) and {@code explanation} ({@link AlertWords}) say what it
     * is about in plain words.
     */
    static Map<String, Object> json(Alert a) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("id", a.id());
        m.put("kind", a.kind().name());
        m.put("kindWords", a.kind().words());
        m.put("room", a.roomName());
        m.put("raisedAt", a.raisedAt().toString());
        m.put("subject", a.subject());
        m.put("text", a.subject());
        m.put("details", a.text());
        m.put("explanation", AlertWords.explanation(a));
        m.put("state", a.state().name());
        m.put("contactsReached", a.contactsReached());
        m.put("closedBy", a.closedBy());
        m.put("reached", AlertReach.lines(a)); // which channel reached whom, in words
        return m;
    }
}
