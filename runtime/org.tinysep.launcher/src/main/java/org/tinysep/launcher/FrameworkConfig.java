package org.tinysep.launcher;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Properties;
import org.osgi.framework.Constants;

/**
 * The framework launch properties of a TinySEP distribution rooted at {@code home}.
 *
 * <p>The state folder ({@code tinysep.var}, default {@code <home>/var}) holds TinySEP's own state; the framework cache
 * {@code <var>/felix-cache} is cleaned on every launch ({@code onFirstInit}): the distribution's
 * folders, not the cache, are the source of truth (bundles/, etc/*.cfg, deploy/). FileInstall watches
 * {@code etc/} for ConfigAdmin {@code *.cfg} files; the shipped {@code etc/org.apache.felix.fileinstall-deploy.cfg}
 * adds a second watcher on {@code deploy/} for hot-deployed jars.
 */
public final class FrameworkConfig {

    /** Framework property holding the distribution directory (usable as {@code ${tinysep.home}} in cfg files). */
    public static final String HOME = "tinysep.home";
    /** Framework property holding the state folder (usable as {@code ${tinysep.var}} in cfg files). */
    public static final String VAR = "tinysep.var";
    /** Felix's hook for its own log output: an {@code org.apache.felix.framework.Logger} instance ({@link FelixLog}). */
    static final String FELIX_LOGGER = "felix.log.logger";
    /**
     * Felix HTTP's key for headers on Jetty's own error pages (a malformed request line or header answers 400 before
     * any servlet filter runs): the same security headers as the web API's filter sets on every answer
     * ({@code org.tinysep.web.api.internal.SecurityFilter}). Entries separated by {@code ##}.
     */
    static final String ERROR_PAGE_HEADERS = "org.apache.felix.http.jetty.errorPageCustomHeaders";
    static final String ERROR_PAGE_HEADER_VALUES = "Content-Security-Policy=default-src 'none'; script-src 'self'; "
            + "style-src 'self'; img-src 'self' data:; connect-src 'self'; form-action 'self'; base-uri 'none'; "
            + "frame-ancestors 'none'##X-Content-Type-Options=nosniff##X-Frame-Options=DENY##Referrer-Policy=no-referrer"
            + "##Cache-Control=no-store";

    private FrameworkConfig() {
    }

    /**
     * @param home       the distribution directory
     * @param daemon     whether the Gogo shell must stay non-interactive
     * @param startLevel the framework's beginning start level (the highest group level)
     * @return launch properties; all values are strings
     */
    public static Map<String, String> properties(Path home, boolean daemon, int startLevel) {
        return properties(home, home.resolve("var"), daemon, startLevel);
    }

    /**
     * @param home       the distribution directory
     * @param var        the state folder
     * @param daemon     whether the Gogo shell must stay non-interactive
     * @param startLevel the framework's beginning start level (the highest group level)
     * @return launch properties; all values are strings
     */
    public static Map<String, String> properties(Path home, Path var, boolean daemon, int startLevel) {
        Map<String, String> p = new HashMap<>();
        p.put(HOME, home.toString());
        p.put(VAR, var.toString());
        p.put(Constants.FRAMEWORK_STORAGE, var.resolve("felix-cache").toString());
        p.put(Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT);
        p.put(Constants.FRAMEWORK_BEGINNING_STARTLEVEL, Integer.toString(startLevel));
        p.put("felix.startlevel.bundle", Integer.toString(startLevel)); // bundles installed later: deploy/, shell
        p.put("felix.log.level", "2");
        // SLF4J is the launcher's (lib/slf4j-api + lib/slf4j-simple): the system bundle exports its packages, so
        // every bundle logs through the one logger the launcher configured. slf4j-api finds slf4j-simple with
        // java.util.ServiceLoader on the class path, as outside OSGi: no Service Loader Mediator (SPI Fly) and no
        // bytecode weaving at start (SPI Fly + ASM would weave every class of Jetty, JAXB and SLF4J at each start)
        p.put(Constants.FRAMEWORK_SYSTEMPACKAGES_EXTRA, Slf4jExports.header());
        // no implicit boot delegation: a bundle sees only what it imports (the launcher's class path holds SLF4J,
        // Felix and the launcher itself)
        p.put("felix.bootdelegation.implicit", "false");
        // FileInstall: etc/ holds ConfigAdmin configurations (<pid>.cfg, <factoryPid>-<name>.cfg)
        p.put("felix.fileinstall.dir", home.resolve("etc").toString());
        p.put("felix.fileinstall.filter", ".*\\.cfg");
        p.put("felix.fileinstall.poll", "1000");
        p.put("felix.fileinstall.noInitialDelay", "true");
        p.put("felix.fileinstall.log.level", "2");
        // its working folder in the state folder, one fixed folder per watcher: no empty /tmp/fileinstall-* folders
        // left behind by every start; deploy/'s watcher: etc/org.apache.felix.fileinstall-deploy.cfg
        p.put("felix.fileinstall.tmpdir", var.resolve("tmp/fileinstall-etc").toString());
        p.put("gosh.home", home.toString()); // the interactive shell reads etc/gosh_profile there ('exit')
        // the web console's HTTP service: this machine only, from its first moment; the host and port of
        // etc/org.apache.felix.http.cfg when it names them (docs/web-api.md), so Jetty binds where configured from
        // the first moment, not at 8080 until FileInstall hands it the file (issue 29)
        Properties http = HttpCfg.read(home.resolve("etc").resolve(HttpCfg.FILE));
        p.put(HttpCfg.HOST, http.getProperty(HttpCfg.HOST, "127.0.0.1"));
        p.put(HttpCfg.PORT, http.getProperty(HttpCfg.PORT, "8080"));
        p.put(ERROR_PAGE_HEADERS, ERROR_PAGE_HEADER_VALUES); // etc/org.apache.felix.http.cfg may override it
        if (daemon) {
            p.put("gosh.args", "--nointeractive");
        }
        return p;
    }
}
