package org.tinysep.houseinformation.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of House Information (pid {@value HouseInformation#PID}). */
@ObjectClassDefinition(name = "House Information", description = "The house plan: rooms, types and neighbours.")
public @interface HouseConfig {

    @AttributeDefinition(description = "The house XML file (thesis Fig 3.7). Empty: ${tinysep.var}/house.xml "
            + "when the property tinysep.var is set, else ${tinysep.home}/var/house.xml, else house.xml in the working "
            + "directory")
    String file() default "";
}
