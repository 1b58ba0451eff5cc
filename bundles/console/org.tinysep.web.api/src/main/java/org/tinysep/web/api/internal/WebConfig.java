package org.tinysep.web.api.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the web console's API and login (pid {@value #PID}); every key is optional. */
@ObjectClassDefinition(name = "TinySEP web console", description = "Login, sessions and passwords of the web console")
public @interface WebConfig {

    String PID = "org.tinysep.web.api";

    @AttributeDefinition(description = "Salted PBKDF2 hash of the installer's password "
            + "(pbkdf2-sha256:<iterations>:<salt>:<hash>); the state folder's web/passwords.properties wins")
    String installer_hash() default "";

    @AttributeDefinition(description = "Salted PBKDF2 hash of the caregiver's password")
    String caregiver_hash() default "";

    @AttributeDefinition(description = "Where tinysep:web-password keeps the hashes; empty = ${tinysep.var}/web/passwords.properties")
    String passwordFile() default "";

    @AttributeDefinition(description = "A session ends after this many minutes without a request")
    int sessionIdleMinutes() default 120;

    @AttributeDefinition(description = "Failed logins per client within loginWindowSeconds before logins are refused")
    int loginMaxFailures() default 5;

    @AttributeDefinition(description = "The rate limit's window in seconds")
    int loginWindowSeconds() default 60;

    @AttributeDefinition(description = "Serve plain HTTP (no TLS) on addresses other than 127.0.0.1 too; passwords "
            + "then cross the network readable (reported as a PROBLEM); default: refused, use HTTPS")
    boolean allowPlainHttpOffLoopback() default false;
}
