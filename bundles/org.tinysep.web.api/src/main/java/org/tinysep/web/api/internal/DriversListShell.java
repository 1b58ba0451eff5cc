package org.tinysep.web.api.internal;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.apache.felix.service.command.CommandProcessor;
import org.apache.felix.service.command.CommandSession;

/**
 * The drivers list (bundle {@code org.tinysep.drivers}, thesis 3.4) through its shell commands, the only interface it
 * offers: {@code tinysep:drivers} (read), {@code reload}, {@code enable <bsn>}, {@code disable <bsn>}, {@code use <bsn> <file>}, run in a
 * Gogo session of the {@link CommandProcessor} service. Symbolic names are checked against
 * {@value #BSN} before they reach the shell. Without Gogo or the drivers list: 503.
 */
final class DriversListShell {

    /** What a bundle symbolic name may look like (nothing a shell would interpret). */
    static final String BSN = "[A-Za-z0-9_][A-Za-z0-9_.-]{0,199}";
    private static final Pattern BSN_PATTERN = Pattern.compile(BSN);
    private static final Pattern FILE_URL = Pattern.compile("file:[A-Za-z0-9/._%~+-]+");

    /** One entry of the drivers list as {@code tinysep:drivers} prints it. */
    record Entry(String application, boolean enabled, String status, String file) {
    }

    private final PlatformView platform;

    DriversListShell(PlatformView platform) {
        this.platform = platform;
    }

    /** @return the list's entries by application (symbolic name), empty when the drivers list is not running */
    Map<String, Entry> entries() {
        Map<String, Entry> out = new LinkedHashMap<>();
        String text;
        try {
            text = run("tinysep:drivers");
        } catch (ApiException e) {
            return out;
        }
        boolean inTable = false;
        for (String line : text.split("\n")) {
            if (!inTable) {
                inTable = line.startsWith("APPLICATION ");
                continue;
            }
            if (line.isBlank()) {
                break;
            }
            String[] cells = line.split(" \\| ", 4);
            if (cells.length == 4) {
                out.put(cells[0].strip(), new Entry(cells[0].strip(), cells[1].strip().equals("yes"), cells[2].strip(),
                        cells[3].strip()));
            }
        }
        return out;
    }

    /** {@code tinysep:drivers enable|disable <bsn>}: @return what the list did, line by line */
    List<String> setEnabled(String bsn, boolean enabled) {
        return lines(run("tinysep:drivers " + (enabled ? "enable " : "disable ") + checked(bsn)));
    }

    /** {@code tinysep:drivers reload}: @return what changed, line by line */
    List<String> reload() {
        return lines(run("tinysep:drivers reload"));
    }

    /**
     * {@code tinysep:drivers use <bsn> <file URL>}: the drivers list loads the application from {@code file} from the
     * next start on. @return what the list says it did
     */
    String use(String bsn, java.nio.file.Path file) {
        String url = file.toUri().toString();
        if (!FILE_URL.matcher(url).matches()) {
            throw ApiException.badRequest("the upload folder's path " + url + " holds characters the shell would"
                    + " interpret");
        }
        return run("tinysep:drivers use " + checked(bsn) + " " + url).strip();
    }

    static String checked(String bsn) {
        if (bsn == null || !BSN_PATTERN.matcher(bsn).matches()) {
            throw ApiException.badRequest("'" + Strings.shorten(String.valueOf(bsn), 60)
                    + "' is not a bundle symbolic name (letters, digits, '.', '_' and '-')");
        }
        return bsn;
    }

    private static List<String> lines(String text) {
        List<String> out = new ArrayList<>();
        for (String l : text.split("\n")) {
            if (!l.isBlank()) {
                out.add(l.strip());
            }
        }
        return out;
    }

    private String run(String command) {
        try {
            return platform.withService(CommandProcessor.class, p -> execute(p, command))
                    .orElseThrow(() -> new ApiException(503, "the drivers list cannot be reached: no shell (Gogo) is running"));
        } catch (NoClassDefFoundError e) {
            throw new ApiException(503, "the drivers list cannot be reached: no shell (Gogo) is installed");
        }
    }

    private static String execute(CommandProcessor processor, String command) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(out, true, StandardCharsets.UTF_8);
        CommandSession session = processor.createSession(new ByteArrayInputStream(new byte[0]), print, print);
        try {
            Object result = session.execute(command);
            print.flush();
            String printed = out.toString(StandardCharsets.UTF_8);
            return result == null ? printed : printed + session.format(result, 0);
        } catch (Exception e) {
            String message = e.getMessage() == null ? e.toString() : e.getMessage();
            if (message.contains("Command not found")) {
                throw new ApiException(503, "the drivers list (bundle org.tinysep.drivers) is not running");
            }
            throw ApiException.badRequest(message);
        } finally {
            session.close();
        }
    }
}
