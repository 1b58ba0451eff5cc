package org.tinysep.benchmarks;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.tinysep.tools.process.ChildProcesses;
import org.tinysep.tools.process.PlatformLaunch;

/** A floor ({@link Bare}) in its own JVM: ask it a question per line, read its RSS, end it. */
final class Child implements AutoCloseable {

    private final Process process;
    private final BufferedReader out;
    private final OutputStream in;
    final double msToReady;

    Child(List<String> jvmOptions, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Machine.java());
        cmd.addAll(PlatformLaunch.jvmArgs(jvmOptions));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), Bare.class.getName()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT);
        pb.environment().keySet().removeAll(MeasuredPlatform.UNSET); // as the platform's, for a fair comparison
        pb.environment().putAll(PlatformLaunch.environment(jvmOptions));
        long t0 = System.nanoTime();
        process = ChildProcesses.track(pb.start());
        out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        in = process.getOutputStream();
        String first = out.readLine();
        msToReady = (System.nanoTime() - t0) / 1e6;
        if (!"ready".equals(first)) {
            throw new IOException("floor " + String.join(" ", args) + " did not start: " + first);
        }
    }

    String ask() throws IOException {
        in.write('\n');
        in.flush();
        return out.readLine();
    }

    long pid() {
        return process.pid();
    }

    @Override
    public void close() throws IOException, InterruptedException {
        in.close();
        if (!process.waitFor(20, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            process.waitFor();
        }
    }
}
