package org.tinysep.sms.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

@ObjectClassDefinition(name = "TinySEP SMS channel", description = "Sends alerts as SMS through a GSM modem driven "
        + "by gammu-smsd (its files spool) and hands replies such as 'OK 3' to the alert service.")
public @interface SmsConfig {

    @AttributeDefinition(description = "gammu-smsd's spool folder: it holds outbox/, inbox/, sent/ and error/ (the "
            + "same paths as outboxpath, inboxpath, sentsmspath and errorsmspath in gammu-smsdrc); empty = "
            + "${tinysep.var}/sms")
    String spoolFolder() default "";

    @AttributeDefinition(description = "gammu-smsd's pid file (its --pid option): without a live process behind it "
            + "the channel is in ERROR and alerts go by the other channels; empty = do not check")
    String pidFile() default "/run/gammu-smsd/gammu-smsd.pid";

    @AttributeDefinition(description = "Seconds an SMS may wait in the outbox before the modem counts as not "
            + "sending (unplugged, no network, no credit)")
    int stuckSeconds() default 60;

    @AttributeDefinition(description = "Most SMS one message may take (longer ones are shortened); 1 to 3")
    int maxParts() default 3;

    @AttributeDefinition(description = "Milliseconds between two looks at the modem's state while an SMS waits in "
            + "the outbox (or the inbox cannot be watched); replies are read as they arrive")
    int pollMillis() default 1000;

    @AttributeDefinition(description = "Seconds between two looks at the modem's state while nothing is pending: "
            + "a gammu-smsd that stopped is said in the event log this much later at most (an alert always sees "
            + "the state of the moment)", min = "1")
    int idleSeconds() default 60;
}
