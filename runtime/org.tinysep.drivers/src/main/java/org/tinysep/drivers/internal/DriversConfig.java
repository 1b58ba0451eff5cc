package org.tinysep.drivers.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the drivers list (pid {@value DriversList#PID}). */
@ObjectClassDefinition(name = "TinySEP drivers list", description = "The application bundles the platform runs.")
public @interface DriversConfig {

    @AttributeDefinition(description = "The drivers list file. Empty: ${tinysep.var}/drivers.xml, else "
            + "${tinysep.home}/var/drivers.xml, else drivers.xml in this bundle's data area")
    String file() default "";

    @AttributeDefinition(description = "Folder whose jars seed a missing list. Empty: ${tinysep.home}/bundles/5-apps")
    String seedFolder() default "";

    @AttributeDefinition(description = "Hot-deploy folder watched by FileInstall: bundles from there are not added "
            + "to the list. Empty: ${tinysep.home}/deploy")
    String deployFolder() default "";

    @AttributeDefinition(description = "Start level of the applications the list installs")
    int startLevel() default 5;

    @AttributeDefinition(description = "Add a bundle installed from a file outside the deploy folder (e.g. the shell's "
            + "install command) to the list, so it is there again after a restart; uninstalling it removes the entry")
    boolean trackShellInstalls() default true;
}
