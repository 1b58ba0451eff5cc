package org.tinysep.sunspot.person.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

@ObjectClassDefinition(name = "Sun SPOT Person: wearers", description = "who wears which person node, as set up")
@interface PersonNamesConfig {

    @AttributeDefinition(description = "<node address>=<name> entries, comma-separated, e.g. "
            + "0014.4F01.0000.0A04=Anna: the node's person parameter when it has none (a name set on the device wins)")
    String persons() default "";
}
