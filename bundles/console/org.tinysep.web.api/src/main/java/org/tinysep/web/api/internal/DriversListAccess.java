package org.tinysep.web.api.internal;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.regex.Pattern;
import org.tinysep.api.drivers.ApplicationEntry;
import org.tinysep.api.drivers.DriversListService;

/**
 * The drivers list (bundle {@code org.tinysep.drivers}, thesis 3.4) through its {@link DriversListService}, looked up
 * per call. Symbolic names are checked against {@value #BSN} before they reach it. Without the drivers list: 503; a
 * request it refuses: 400 with its words.
 */
final class DriversListAccess {

    /** What a bundle symbolic name may look like. */
    static final String BSN = "[A-Za-z0-9_][A-Za-z0-9_.-]{0,199}";
    private static final Pattern BSN_PATTERN = Pattern.compile(BSN);

    private final PlatformView platform;

    DriversListAccess(PlatformView platform) {
        this.platform = platform;
    }

    /** @return the list's entries by application (symbolic name), empty when the drivers list is not running */
    Map<String, ApplicationEntry> entries() {
        Map<String, ApplicationEntry> out = new LinkedHashMap<>();
        platform.withService(DriversListService.class, DriversListService::applications)
                .ifPresent(list -> list.forEach(e -> out.put(e.application(), e)));
        return out;
    }

    /** Enables or disables an application: @return what the list did, line by line */
    List<String> setEnabled(String bsn, boolean enabled) {
        String checked = checked(bsn);
        return call(list -> list.setEnabled(checked, enabled));
    }

    /** Re-reads the list file: @return what changed, line by line */
    List<String> reload() {
        return call(DriversListService::reload);
    }

    /** The drivers list loads the application from {@code file} from the next start on. @return what it did */
    String use(String bsn, Path file) {
        String checked = checked(bsn);
        return call(list -> list.use(checked, file.toUri().toString())).strip();
    }

    static String checked(String bsn) {
        if (bsn == null || !BSN_PATTERN.matcher(bsn).matches()) {
            throw ApiException.badRequest("'" + Strings.shorten(String.valueOf(bsn), 60)
                    + "' is not a bundle symbolic name (letters, digits, '.', '_' and '-')");
        }
        return bsn;
    }

    private <R> R call(Function<DriversListService, R> use) {
        try {
            return platform.withService(DriversListService.class, use).orElseThrow(() -> new ApiException(503,
                    "the drivers list (bundle org.tinysep.drivers) is not running"));
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw ApiException.badRequest(e.getMessage());
        }
    }
}
