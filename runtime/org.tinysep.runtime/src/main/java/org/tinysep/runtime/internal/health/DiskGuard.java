package org.tinysep.runtime.internal.health;

import java.nio.file.Path;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.log.EventLog;
import org.tinysep.device.support.files.StateFolder;

/**
 * Runs {@link DiskCheck} on the state folder ({@code ${tinysep.var}}, its log history in {@code log/}) every
 * {@code checkSeconds}, from its first moment. Without a state folder (a bare test framework) it does nothing.
 */
@Component(immediate = true, service = {}, configurationPid = DiskConfig.PID)
@Designate(ocd = DiskConfig.class)
public final class DiskGuard {

    @Reference
    private EventLog eventLog;
    private ScheduledExecutorService timer;

    @Activate
    void activate(DiskConfig config, BundleContext context) {
        Path var = StateFolder.resolve(null, context, "log").map(Path::getParent).orElse(null);
        if (var == null || config.minFreeMegabytes() <= 0) {
            return;
        }
        DiskCheck check = new DiskCheck(var, var.resolve("log"), config.minFreeMegabytes(), eventLog);
        timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "tinysep-disk-watch");
            t.setDaemon(true);
            return t;
        });
        timer.scheduleWithFixedDelay(check::check, 0, Math.max(1, config.checkSeconds()), TimeUnit.SECONDS);
    }

    @Deactivate
    void deactivate() {
        if (timer != null) {
            timer.shutdownNow();
        }
    }
}
