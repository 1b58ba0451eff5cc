package org.tinysep.inactivity.internal;

import java.lang.annotation.Annotation;

/** The configuration's declared defaults, read from the annotation itself so tests follow any change. */
final class InactivityConfigDefaults implements InactivityConfig {

    private static String text(String attribute) {
        try {
            return (String) InactivityConfig.class.getMethod(attribute).getDefaultValue();
        } catch (NoSuchMethodException e) {
            throw new IllegalStateException(e);
        }
    }

    @Override
    public int defaultLimitMinutes() {
        try {
            return (Integer) InactivityConfig.class.getMethod("defaultLimitMinutes").getDefaultValue();
        } catch (NoSuchMethodException e) {
            throw new IllegalStateException(e);
        }
    }

    @Override
    public String typeLimits() {
        return text("typeLimits");
    }

    @Override
    public String roomLimits() {
        return text("roomLimits");
    }

    @Override
    public String timeZone() {
        return text("timeZone");
    }

    @Override
    public Class<? extends Annotation> annotationType() {
        return InactivityConfig.class;
    }
}
