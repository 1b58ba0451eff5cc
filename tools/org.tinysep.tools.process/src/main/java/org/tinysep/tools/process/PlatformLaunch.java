package org.tinysep.tools.process;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

/**
 * How to start a distribution: {@code java <JVM options> -jar tinysep.jar <launcher arguments>} in its home, with
 * {@code etc/*.cfg} files written first, the child's standard error appended to a log file and its standard output
 * read line by line. {@link #start} waits for the banner (and for the shell, unless {@link #daemon()}); {@link
 * #launch} returns at once.
 */
public final class PlatformLaunch {

    /** How long {@link #start()} waits by default for the banner and the shell. */
    public static final Duration START_TIMEOUT = Duration.ofSeconds(90);

    private final Path home;
    private String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
    private Path jar = Path.of(DistributionCopy.JAR);
    private final List<String> jvm = new ArrayList<>();
    private final List<String> args = new ArrayList<>();
    private final Map<String, String> env = new LinkedHashMap<>();
    private final Set<String> unset = new LinkedHashSet<>(List.of("TINYSEP_DAEMON"));
    private final Map<String, String> cfgs = new LinkedHashMap<>();
    private Path log;
    private Path stdoutCopy;
    private Consumer<String> eachLine = line -> { };
    private boolean daemon;
    private Duration stopTimeout = Duration.ofSeconds(30);

    PlatformLaunch(Path home) {
        this.home = home;
        this.log = home.resolve("platform.log");
    }

    /**
     * JVM options, as {@code etc/jvm.options} and the benchmarks list them: entries starting with {@code -} go on
     * the command line, {@code NAME=value} entries into the child's environment. @return this
     */
    public PlatformLaunch jvm(List<String> options) {
        jvm.addAll(jvmArgs(options));
        env.putAll(environment(options));
        return this;
    }

    /** Launcher arguments after {@code -jar tinysep.jar} (e.g. {@code --var DIR}, {@code --home DIR}). @return this */
    public PlatformLaunch args(String... launcherArgs) {
        args.addAll(List.of(launcherArgs));
        return this;
    }

    /** Runs without the shell ({@code --daemon}): stopped by SIGTERM rather than by the end of its input. @return this */
    public PlatformLaunch daemon() {
        daemon = true;
        args.add(0, "--daemon");
        return this;
    }

    /** The jar to run (default {@code tinysep.jar} in the home). @return this */
    public PlatformLaunch jar(Path launcherJar) {
        jar = launcherJar.toAbsolutePath();
        return this;
    }

    /** The java executable (default: the one running this JVM). @return this */
    public PlatformLaunch java(String executable) {
        java = executable;
        return this;
    }

    /** Removes {@code names} from the child's environment (TINYSEP_DAEMON always: the launch says). @return this */
    public PlatformLaunch unsetEnv(String... names) {
        unset.addAll(List.of(names));
        return this;
    }

    /** Writes {@code <home>/etc/<pid>.cfg} with {@code text} ({@code key=value} lines) before the start. @return this */
    public PlatformLaunch cfg(String pid, String text) {
        cfgs.put(pid, text);
        return this;
    }

    /** Appends the child's standard error (its log) to {@code file} (default {@code <home>/platform.log}). @return this */
    public PlatformLaunch log(Path file) {
        log = file;
        return this;
    }

    /** Also writes every standard output line to {@code file}. @return this */
    public PlatformLaunch stdoutCopy(Path file) {
        stdoutCopy = file;
        return this;
    }

    /** Shows every standard output line to {@code listener} first, on the reader thread. @return this */
    public PlatformLaunch eachLine(Consumer<String> listener) {
        eachLine = listener;
        return this;
    }

    /** How long {@link PlatformProcess#close()} waits for an orderly stop before it kills (default 30 s). @return this */
    public PlatformLaunch stopTimeout(Duration timeout) {
        stopTimeout = timeout;
        return this;
    }

    /** {@link #start(Duration)} with {@link #START_TIMEOUT}. */
    public PlatformProcess start() throws IOException {
        return start(START_TIMEOUT);
    }

    /**
     * Starts the child and waits for its banner and, unless {@link #daemon()}, for its shell's answer.
     *
     * @throws IOException when it cannot start, ends, or is not up within {@code timeout}: the message carries its
     *                     last output lines and log lines; the child is then killed
     */
    public PlatformProcess start(Duration timeout) throws IOException {
        PlatformProcess p = launch();
        p.awaitUp(timeout);
        return p;
    }

    /** Starts the child and returns at once. */
    public PlatformProcess launch() throws IOException {
        for (Map.Entry<String, String> c : cfgs.entrySet()) {
            DistributionCopy.cfg(home, c.getKey(), c.getValue());
        }
        Files.createDirectories(log.toAbsolutePath().getParent());
        ProcessBuilder builder = new ProcessBuilder(command()).directory(home.toFile())
                .redirectError(ProcessBuilder.Redirect.appendTo(log.toFile()));
        unset.forEach(builder.environment()::remove);
        builder.environment().putAll(env);
        long startNanos = System.nanoTime();
        Process process = ChildProcesses.track(builder.start());
        return new PlatformProcess(process, this, startNanos);
    }

    /** @return the command line {@link #launch()} runs */
    public List<String> command() {
        List<String> command = new ArrayList<>();
        command.add(java);
        command.addAll(jvm);
        command.addAll(List.of("-jar", jar.toString()));
        command.addAll(args);
        return command;
    }

    Path logFile() {
        return log;
    }

    Path stdoutCopyFile() {
        return stdoutCopy;
    }

    Consumer<String> lineListener() {
        return eachLine;
    }

    boolean isDaemon() {
        return daemon;
    }

    Duration closeTimeout() {
        return stopTimeout;
    }

    /** @return the JVM arguments of an options list (its entries starting with {@code -}) */
    public static List<String> jvmArgs(List<String> options) {
        return options.stream().filter(o -> o.startsWith("-")).toList();
    }

    /** @return the environment entries of an options list ({@code NAME=value}, as {@code etc/jvm.options} has them) */
    public static Map<String, String> environment(List<String> options) {
        Map<String, String> env = new LinkedHashMap<>();
        for (String o : options) {
            if (!o.startsWith("-") && o.contains("=")) {
                env.put(o.substring(0, o.indexOf('=')), o.substring(o.indexOf('=') + 1));
            }
        }
        return env;
    }
}
