package org.tinysep.helpbutton.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

@ObjectClassDefinition(name = "TinySEP Help Button", description = "Holding a switch of the node a person wears "
        + "raises a HELP alert at once through the alert service; a second press soon after cancels it as pressed "
        + "by mistake.")
public @interface HelpButtonConfig {

    @AttributeDefinition(description = "How long a switch must be held to call for help, milliseconds (100..10000). "
            + "A shorter press is logged and raises nothing")
    int holdMillis() default 1000;

    @AttributeDefinition(description = "Seconds after the help call during which a second press cancels it as "
            + "pressed by mistake (0..120; 0 = a help call cannot be cancelled from the node)")
    int cancelSeconds() default 10;

    @AttributeDefinition(description = "The help switch: 1 (SW1), 2 (SW2), or 0 = either")
    int button() default 0;

    @AttributeDefinition(description = "Zone of the times in messages, e.g. Europe/Berlin; empty = the system's")
    String timeZone() default "";
}
