package org.tinysep.mqtt.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration {@code org.tinysep.mqtt}: the bridge stays idle while {@code brokerUrl} is empty. */
@ObjectClassDefinition(name = "TinySEP MQTT bridge",
        description = "Publishes the flat's state and alerts to an MQTT broker and takes commands from it")
@interface MqttConfig {

    @AttributeDefinition(description = "tcp://host:1883 or ssl://host:8883; empty = the bridge is idle")
    String brokerUrl() default "";

    @AttributeDefinition(description = "the flat's id: MQTT client id and second topic level (letters, digits, - _ .)")
    String flatId() default "flat";

    @AttributeDefinition(description = "MQTT user name; empty (and no keyStore) = anonymous, refused unless "
            + "allowAnonymous")
    String username() default "";

    @AttributeDefinition(description = "file whose first line is the MQTT password (owner-only); default "
            + "${tinysep.var}/secrets/mqtt.password")
    String passwordFile() default "";

    @AttributeDefinition(description = "trust store (PKCS12 or JKS) with the broker's CA certificate, for ssl://;"
            + " empty = the JDK's default CAs")
    String trustStore() default "";

    @AttributeDefinition(description = "password of the trust store (not a secret: it only guards integrity)")
    String trustStorePassword() default "changeit";

    @AttributeDefinition(description = "key store (PKCS12) with this flat's client certificate and key; empty = none")
    String keyStore() default "";

    @AttributeDefinition(description = "file whose first line is the key store's password")
    String keyStorePasswordFile() default "";

    @AttributeDefinition(description = "first topic level")
    String topicPrefix() default "tinysep";

    @AttributeDefinition(description = "Home Assistant discovery prefix; empty = no discovery")
    String discoveryPrefix() default "homeassistant";

    @AttributeDefinition(description = "seconds between platform heartbeats (P/F/platform)")
    int heartbeatSeconds() default 60;

    @AttributeDefinition(description = "seconds the broker keeps this flat's session (and commands sent to it) "
            + "while the flat is disconnected")
    int sessionExpirySeconds() default 3600;

    @AttributeDefinition(description = "folder of the outbox on disk; default ${tinysep.var}/mqtt")
    String queueDir() default "";

    @AttributeDefinition(description = "seconds between two reads of the devices' state")
    int pollSeconds() default 1;

    @AttributeDefinition(description = "true = connect even without a login (no username, no keyStore); anyone "
            + "on such a broker can read and publish this flat's topics. Default false: the bridge does not connect")
    boolean allowAnonymous() default false;

    @AttributeDefinition(description = "file whose first line is this flat's key (at least 32 characters, "
            + "owner-only): signs the flat's messages and checks signed commands; default ${tinysep.var}/secrets/mqtt.key")
    String keyFile() default "";

    @AttributeDefinition(name = "commands.ack", description = "acknowledgements over MQTT: off, signed (default) or "
            + "unsigned")
    String commands_ack() default "signed";

    @AttributeDefinition(name = "commands.actuators", description = "switching lights, heaters, speakers over MQTT:"
            + " off (default), signed or unsigned (Home Assistant's plain ON/OFF)")
    String commands_actuators() default "off";

    @AttributeDefinition(name = "commands.maxAgeSeconds", description = "a signed command older (or further in the "
            + "future) than this, by this computer's clock, is refused")
    int commands_maxAgeSeconds() default 300;
}
