package org.tinysep.drivers.internal;

import java.util.Optional;
import java.util.stream.Stream;

/**
 * The applications that watch the person: stopping, removing or replacing one of them lowers how
 * well the person is watched, so it is a "Monitoring reduced: " signal for the caregivers.
 */
enum WatchingApp {
    INACTIVITY("org.tinysep.inactivity", "Inactivity Recognition",
            "nobody is told if the person stops moving (no inactivity alert)"),
    FLAT_OCCUPANCY("org.tinysep.flatoccupancy", "Flat Occupancy",
            "TinySEP no longer knows whether the person is at home, so Inactivity Recognition cannot watch"),
    ALERTS("org.tinysep.alerts", "the alert service",
            "alerts are no longer repeated or passed on until someone acknowledges them, and no daily summary is sent"),
    SENSOR_HEALTH("org.tinysep.sensorhealth", "Sensor Health",
            "nobody is told when a sensor stops reporting or its battery runs low"),
    MAIL("org.tinysep.mailmanager", "the Mail Manager", "no alert or notice can be sent by e-mail");

    private final String symbolicName;
    private final String title;
    private final String loss;

    WatchingApp(String symbolicName, String title, String loss) {
        this.symbolicName = symbolicName;
        this.title = title;
        this.loss = loss;
    }

    static Optional<WatchingApp> of(String symbolicName) {
        return Stream.of(values()).filter(a -> a.symbolicName.equals(symbolicName)).findFirst();
    }

    String symbolicName() {
        return symbolicName;
    }

    /** e.g. "Monitoring reduced: Inactivity Recognition (org.tinysep.inactivity 0.1.0) was stopped: nobody …" */
    String stopped(String version) {
        return "Monitoring reduced: " + title + " (" + symbolicName + " " + version + ") was stopped or disabled: "
                + loss + ". To watch again: tinysep:drivers enable " + symbolicName
                + " (or Enable on the web console's Applications page)";
    }

    String removed(String version) {
        return "Monitoring reduced: " + title + " (" + symbolicName + " " + version + ") was removed: " + loss
                + ". To watch again: put it back in the drivers list (docs/runtime-changes.md)";
    }

    String disabledAtStart() {
        return "Monitoring reduced: " + title + " (" + symbolicName + ") is disabled in the drivers list and did "
                + "not start: " + loss + ". To watch again: tinysep:drivers enable " + symbolicName;
    }

    String replaced(String oldVersion, String oldLocation, String newVersion, String newLocation) {
        return "Monitoring reduced: " + title + " (" + symbolicName + ") was replaced: version " + oldVersion
                + " from " + oldLocation + " by version " + newVersion + " from " + newLocation + ". The code that "
                + "watches the person is no longer the one installed with TinySEP; if nobody meant this, put the "
                + "distribution's version back (tinysep:drivers use " + symbolicName + " <file>, docs/runtime-changes.md)";
    }
}
