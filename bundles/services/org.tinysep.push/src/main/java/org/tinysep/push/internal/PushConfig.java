package org.tinysep.push.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

@ObjectClassDefinition(name = "TinySEP push channel", description = "Sends alerts as push notifications through an "
        + "ntfy server (HTTP publish as JSON, over TLS only); a contact's push address is the topic their phone's "
        + "ntfy app subscribes to.")
public @interface PushConfig {

    @AttributeDefinition(description = "The ntfy server, https only, e.g. https://ntfy.example.org; empty = no push "
            + "(the channel is in ERROR and alerts go by the other channels)")
    String server() default "";

    @AttributeDefinition(description = "File holding the access token (first line), sent as 'Authorization: Bearer'; "
            + "keep it readable by its owner only; empty = ${tinysep.var}/secrets/push.token; a missing file = no "
            + "token")
    String tokenFile() default "";

    @AttributeDefinition(description = "PEM file with the certificate(s) to trust for a server with its own "
            + "certificate; empty = the certificates the Java runtime trusts")
    String trustedCertificates() default "";

    @AttributeDefinition(description = "ntfy priority of alerts, 1 (min) to 5 (max, urgent)")
    int priority() default 5;

    @AttributeDefinition(description = "Seconds to connect and to wait for the server's answer")
    int timeoutSeconds() default 5;
}
