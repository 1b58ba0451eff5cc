package org.tinysep.launcher;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Command-line options of the launcher. A parser of its own rather than picocli (which the simulator, the evaluation
 * and the benchmarks use, tools/org.tinysep.tools.cli): the platform's start time counts, and picocli's classes take
 * 0.1 s and more of class loading before Felix starts. Refusals read as picocli's do ({@code Unknown option: '--x'});
 * {@link Main} prints them as {@code error: ...}, then the usage, with exit code 2.
 *
 * @param daemon run without the interactive Gogo shell until SIGTERM ({@code --daemon} or {@code TINYSEP_DAEMON=1})
 * @param home   the distribution directory holding {@code bundles/}, {@code etc/} and {@code deploy/}
 * @param var    the state folder (framework property {@code tinysep.var}): the drivers list, the house, the mail
 *               spool, the framework cache; default {@code <home>/var}
 * @param help   print the usage and exit
 * @param supervise run the platform as a supervised child process, restarted when it fails or hangs
 *                  ({@code --supervise}: {@link Supervisor})
 * @param headless  the headless gateway profile ({@code --headless} or {@code TINYSEP_HEADLESS=1}): the web console
 *                  ({@code bundles/4-web}: its HTTP service, Jetty, and the console's bundles) is not installed
 */
public record Options(boolean daemon, Path home, Path var, boolean help, boolean supervise, boolean headless) {

    /** Options with the web console (not headless). */
    public Options(boolean daemon, Path home, Path var, boolean help, boolean supervise) {
        this(daemon, home, var, help, supervise, false);
    }

    /** Options whose state folder is {@code <home>/var}. */
    public Options(boolean daemon, Path home, boolean help) {
        this(daemon, home, home.resolve("var"), help);
    }

    /** Options without supervision. */
    public Options(boolean daemon, Path home, Path var, boolean help) {
        this(daemon, home, var, help, false);
    }

    /** Environment variable that switches daemon mode on ({@code 1}, {@code true} or {@code yes}). */
    public static final String DAEMON_ENV = "TINYSEP_DAEMON";
    /** Environment variable that switches the headless gateway profile on ({@code 1}, {@code true} or {@code yes}). */
    public static final String HEADLESS_ENV = "TINYSEP_HEADLESS";
    /** System property naming the distribution directory. */
    public static final String HOME_PROPERTY = "tinysep.home";
    /** System property naming the state folder. */
    public static final String VAR_PROPERTY = "tinysep.var";

    /** The usage text printed by {@code --help} and on a bad argument. */
    public static final String USAGE = String.join(System.lineSeparator(),
            "Usage: java -jar tinysep.jar [--daemon] [--headless] [--supervise] [--home DIR] [--var DIR] [--web-password ROLE]"
                    + " [--help]",
            "  --daemon, -d   no interactive shell; run until SIGTERM (also: TINYSEP_DAEMON=1)",
            "  --headless     headless gateway: no web console and no HTTP port (bundles/4-web is not installed;",
            "                 also: TINYSEP_HEADLESS=1); less memory, docs/footprint.md",
            "  --home DIR     distribution directory (default: -Dtinysep.home, else the folder of tinysep.jar,",
            "                 else the current directory)",
            "  --var DIR      state folder: drivers list, house, mail spool, framework cache (default:",
            "                 -Dtinysep.var, else <home>/var)",
            "  --supervise    run TinySEP as a child process (daemon) and restart it when it ends with an error or",
            "                 stops responding (docs/operations.md)",
            "  --web-password installer|caregiver",
            "                 set that web console password (asked on the terminal, or one line on standard input)",
            "                 and exit: the way in without the shell, e.g. for --daemon",
            "  --help, -h     print this text");

    /**
     * Parses the arguments.
     *
     * @param args        command-line arguments
     * @param env         environment variables (for {@value #DAEMON_ENV})
     * @param defaultHome the home used when {@code --home} is absent
     * @throws IllegalArgumentException on an unknown argument or a missing value
     */
    public static Options parse(List<String> args, Map<String, String> env, Path defaultHome) {
        boolean daemon = isTrue(env.get(DAEMON_ENV));
        boolean headless = isTrue(env.get(HEADLESS_ENV));
        boolean help = false;
        boolean supervise = false;
        Path home = defaultHome;
        String varProperty = System.getProperty(VAR_PROPERTY);
        Path var = varProperty == null || varProperty.isBlank() ? null : Path.of(varProperty);
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            switch (arg) {
                case "--daemon", "-d" -> daemon = true;
                case "--help", "-h" -> help = true;
                case "--supervise" -> supervise = true;
                case "--headless" -> headless = true;
                case "--home" -> {
                    if (i + 1 >= args.size()) {
                        throw new IllegalArgumentException("--home needs a directory");
                    }
                    home = Path.of(args.get(++i));
                }
                case "--var" -> {
                    if (i + 1 >= args.size()) {
                        throw new IllegalArgumentException("--var needs a directory");
                    }
                    var = Path.of(args.get(++i));
                }
                default -> {
                    if (arg.startsWith("--home=") && arg.length() > "--home=".length()) {
                        home = Path.of(arg.substring("--home=".length()));
                    } else if (arg.startsWith("--var=") && arg.length() > "--var=".length()) {
                        var = Path.of(arg.substring("--var=".length()));
                    } else {
                        throw new IllegalArgumentException((arg.startsWith("-") ? "Unknown option: '"
                                : "Unmatched argument: '") + arg + "'");
                    }
                }
            }
        }
        Path absoluteHome = home.toAbsolutePath().normalize();
        Path absoluteVar = (var == null ? absoluteHome.resolve("var") : var.toAbsolutePath()).normalize();
        return new Options(daemon, absoluteHome, absoluteVar, help, supervise, headless);
    }

    /**
     * The home used without {@code --home}: {@code -Dtinysep.home}, else the directory of the launcher jar
     * when it holds a {@code bundles/} folder, else the current directory.
     */
    public static Path defaultHome(Path launcherLocation) {
        String property = System.getProperty(HOME_PROPERTY);
        if (property != null && !property.isBlank()) {
            return Path.of(property);
        }
        if (launcherLocation != null && Files.isRegularFile(launcherLocation)) {
            Path dir = launcherLocation.toAbsolutePath().getParent();
            if (dir != null && Files.isDirectory(dir.resolve("bundles"))) {
                return dir;
            }
        }
        return Path.of("");
    }

    static boolean isTrue(String value) {
        if (value == null) {
            return false;
        }
        return switch (value.trim().toLowerCase(Locale.ROOT)) {
            case "1", "true", "yes", "on" -> true;
            default -> false;
        };
    }
}
