package org.tinysep.mqtt.board.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

@ObjectClassDefinition(name = "TinySEP central alert board", description = "A care centre's board of many flats "
        + "on one MQTT broker: status, occupancy, open alerts (acknowledge travels back), offline sensors, low "
        + "batteries. Idle while no broker is configured.")
public @interface BoardConfig {

    @AttributeDefinition(description = "Broker URL, e.g. tcp://127.0.0.1:1883 or ssl://broker:8883; empty = idle")
    String brokerUrl() default "";

    @AttributeDefinition(description = "MQTT client id of the board (each board on a broker needs its own)")
    String clientId() default "tinysep-board";

    @AttributeDefinition(description = "Broker user name; empty = none")
    String username() default "";

    @AttributeDefinition(description = "Broker password (kept by ConfigAdmin only; never shown, logged or written by the board)",
            type = org.osgi.service.metatype.annotations.AttributeType.PASSWORD)
    String password() default "";

    @AttributeDefinition(description = "Trust store (PKCS12 or JKS file) for ssl:// brokers; empty = the JVM's")
    String trustStore() default "";

    @AttributeDefinition(description = "Password of the trust store",
            type = org.osgi.service.metatype.annotations.AttributeType.PASSWORD)
    String trustStorePassword() default "";

    @AttributeDefinition(description = "Topic prefix of the flats' bridges (their topicPrefix)")
    String topicPrefix() default "tinysep";

    @AttributeDefinition(description = "A flat is silent after this many missed heartbeats (× its heartbeatSeconds)")
    int missedHeartbeats() default 3;

    @AttributeDefinition(description = "A flat is silent when its newest daily summary is older than this many hours")
    int summaryHours() default 26;

    @AttributeDefinition(description = "A battery at or below this percentage is listed as low")
    int lowBatteryPercent() default 20;

    @AttributeDefinition(description = "Most flats tracked; messages of further flats are counted and dropped")
    int maxFlats() default 5000;

    @AttributeDefinition(description = "Name sent as the acknowledger when the page does not give one")
    String acknowledgedBy() default "care centre";

    @AttributeDefinition(description = "Zone of the times shown, e.g. Europe/Berlin; empty = the system's")
    String timeZone() default "";
}
