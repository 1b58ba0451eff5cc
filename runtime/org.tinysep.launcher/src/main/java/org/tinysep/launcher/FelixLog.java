package org.tinysep.launcher;

import org.osgi.framework.Bundle;
import org.osgi.framework.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Felix's own log output (framework configuration {@code felix.log.logger}, which Felix requires to be a
 * {@link org.apache.felix.framework.Logger}), written through SLF4J as one line per entry. Stack traces only
 * appear with DEBUG enabled for {@code org.tinysep.launcher.FelixLog}.
 */
public final class FelixLog extends org.apache.felix.framework.Logger {

    private static final Logger LOG = LoggerFactory.getLogger(FelixLog.class);

    @Override
    protected void doLog(Bundle bundle, @SuppressWarnings("rawtypes") ServiceReference ref, int level, String message,
                         Throwable throwable) {
        String source = bundle != null ? bundle.getSymbolicName() + " [" + bundle.getBundleId() + "]: "
                : ref != null ? ref + ": " : "";
        String line = source + message + (throwable == null ? "" : " — " + Failures.describe(throwable));
        Throwable trace = LOG.isDebugEnabled() ? throwable : null;
        switch (level) {
            case LOG_ERROR -> LOG.error("{}", line, trace);
            case LOG_WARNING -> LOG.warn("{}", line, trace);
            case LOG_INFO -> LOG.info("{}", line, trace);
            default -> LOG.debug("{}", line, trace);
        }
    }
}
