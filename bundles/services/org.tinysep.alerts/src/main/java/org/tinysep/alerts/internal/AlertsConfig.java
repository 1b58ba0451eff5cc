package org.tinysep.alerts.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

@ObjectClassDefinition(name = "TinySEP Alerts", description = "Keeps alerts until acknowledged, repeats and "
        + "escalates them along a contact list, sends the all clear and a daily summary.")
public @interface AlertsConfig {

    @AttributeDefinition(description = "Escalation list: e-mail addresses, comma-separated, in the order they are "
            + "told. The first message goes to the first, each escalation adds the next. Empty = the Mail Manager's "
            + "recipients (no escalation, only repeats)")
    String contacts() default "";

    @AttributeDefinition(description = "Minutes after which an unacknowledged alert is sent again to the contacts "
            + "told so far (and again after each further period); 0 = never")
    int repeatMinutes() default 10;

    @AttributeDefinition(description = "Minutes without acknowledgement after which the next contact is told "
            + "(contact n+1 after n times this); 0 = never escalate")
    int escalateMinutes() default 15;

    @AttributeDefinition(description = "Time of day (HH:mm) of the daily 'TinySEP is running' summary to the "
            + "Mail Manager's recipients; empty = no summary")
    String summaryTime() default "08:00";

    @AttributeDefinition(description = "Zone of the summary time and of times in messages, e.g. Europe/Berlin; "
            + "empty = the system's")
    String timeZone() default "";

    @AttributeDefinition(description = "Seconds a sensor must stay away before the caregivers get a 'monitoring "
            + "reduced' notice about it; a sensor back within this time (a platform start, a driver update) mails "
            + "nothing. 0 = at once")
    int noticeGraceSeconds() default 60;

    @AttributeDefinition(description = "File the alerts are kept in; empty = ${tinysep.var}/alerts/alerts.properties")
    String stateFile() default "";
}
