package org.tinysep.itests.serial;

import static org.ops4j.pax.exam.CoreOptions.systemProperty;

import java.util.List;
import org.ops4j.pax.exam.Option;
import org.osgi.framework.InvalidSyntaxException;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.itests.TinySepTestSupport;

/** Base of the serial bus radio tests: the framework as usual, plus what jSerialComm needs in tests. */
abstract class SerialTestSupport extends TinySepTestSupport {

    /**
     * jSerialComm loads its JNI library once per class loader, and the JVM refuses the same library file in a
     * second class loader: every Felix framework after the first in this JVM (one per test class or method) would
     * fail to open any port ("Cannot load native library"). A random file name per load avoids that.
     */
    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.add(systemProperty("jSerialComm.library.randomizeNativeName").value("true"));
        return o;
    }

    /** @return the driver parameter's value, or "" */
    static String parameter(Driver driver, String key) {
        return driver.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElse("");
    }

    /** @return how many services of {@code type} match {@code filter} now */
    int count(Class<?> type, String filter) {
        try {
            return context.getServiceReferences(type, filter).size();
        } catch (InvalidSyntaxException e) {
            throw new IllegalArgumentException(filter, e);
        }
    }
}
