package org.tinysep.itests.serial;

import org.osgi.framework.InvalidSyntaxException;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.itests.TinySepTestSupport;

/** Base of the serial bus radio tests: helpers to read driver parameters and count services. */
abstract class SerialTestSupport extends TinySepTestSupport {

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
