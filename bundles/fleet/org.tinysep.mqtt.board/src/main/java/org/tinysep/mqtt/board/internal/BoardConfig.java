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

    @AttributeDefinition(description = "Broker user name; empty = anonymous, refused unless allowAnonymous")
    String username() default "";

    @AttributeDefinition(description = "File whose first line is the broker password (owner-only, chmod 600), read "
            + "when the board starts; empty = ${tinysep.var}/secrets/mqtt-board.password")
    String passwordFile() default "";

    @AttributeDefinition(description = "Deprecated: the broker password inline (kept in ConfigAdmin's files); still "
            + "used with a warning, put it into passwordFile instead",
            type = org.osgi.service.metatype.annotations.AttributeType.PASSWORD)
    String password() default "";

    @AttributeDefinition(description = "true = connect without a login; anyone on such a broker can fake flats and "
            + "alerts and acknowledge alerts. Default false: without a login the board does not connect")
    boolean allowAnonymous() default false;

    @AttributeDefinition(description = "Folder of the flats' keys, one file <flatId>.key per flat (its first line is "
            + "the key of that flat's bridge, keyFile); the board follows only these flats and only their signed "
            + "messages; empty = ${tinysep.var}/secrets/flats")
    String flatKeyDir() default "";

    @AttributeDefinition(description = "Flat ids the board follows, comma separated; empty or * = every flat with a "
            + "key file in flatKeyDir")
    String flats() default "*";

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
