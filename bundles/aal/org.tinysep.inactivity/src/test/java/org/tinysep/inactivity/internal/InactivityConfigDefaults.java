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

    private static int number(String attribute) {
        try {
            return (Integer) InactivityConfig.class.getMethod(attribute).getDefaultValue();
        } catch (NoSuchMethodException e) {
            throw new IllegalStateException(e);
        }
    }

    @Override
    public Detector detector() {
        try {
            return (Detector) InactivityConfig.class.getMethod("detector").getDefaultValue();
        } catch (NoSuchMethodException e) {
            throw new IllegalStateException(e);
        }
    }

    @Override
    public int learnMinDays() {
        return number("learnMinDays");
    }

    @Override
    public int learnHistoryDays() {
        return number("learnHistoryDays");
    }

    @Override
    public int learnFloorMinutes() {
        return number("learnFloorMinutes");
    }

    @Override
    public int learnMinPeriodsToShorten() {
        return number("learnMinPeriodsToShorten");
    }

    @Override
    public int residents() {
        return number("residents");
    }

    @Override
    public int nightStartHour() {
        return number("nightStartHour");
    }

    @Override
    public int nightEndHour() {
        return number("nightEndHour");
    }

    @Override
    public int personMovingAboveMg() {
        return number("personMovingAboveMg");
    }

    @Override
    public int personMovingWithinSeconds() {
        return number("personMovingWithinSeconds");
    }

    @Override
    public int personNotWornMinutes() {
        return number("personNotWornMinutes");
    }

    @Override
    public Class<? extends Annotation> annotationType() {
        return InactivityConfig.class;
    }
}
