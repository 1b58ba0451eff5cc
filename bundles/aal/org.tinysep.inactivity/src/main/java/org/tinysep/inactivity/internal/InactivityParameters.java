package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.List;
import org.tinysep.api.device.Parameter;

/** The Inactivity Recognition device's read-only parameters: its state and why, in words (the console shows them). */
final class InactivityParameters {

    private InactivityParameters() {
    }

    static List<Parameter> of(InactivityLogic logic, LimitPolicy policy, HelpCall help, RoomActivity rooms,
            ActivityFactory activities, PersonWatches persons) {
        synchronized (logic) {
            return List.of(
                    Parameter.readOnly("state", logic.state(), "current state"),
                    Parameter.readOnly("since", logic.since(), "when it was entered"),
                    Parameter.readOnly("deadline", logic.deadline().map(Instant::toString).orElse(""),
                            "when help is called if nothing happens"),
                    Parameter.readOnly("lastActivity", logic.lastActivity()
                            .map(a -> a.description() + " in " + a.roomName() + " at " + a.at()).orElse(""),
                            "the last activity seen"),
                    Parameter.readOnly("limitReason", logic.lastActivity().map(Activity::explanation).orElse(""),
                            "why the deadline is what it is (detector " + policy.name() + ")"),
                    Parameter.readOnly("alert", logic.alert().map(help::subject).orElse(""), "the raised alert"),
                    Parameter.readOnly("lastActivityPerRoom", rooms.describe(), "room uid = last activity there"),
                    Parameter.readOnly("knownRooms", activities.knownRooms(), "rooms known from House Information"),
                    Parameter.readOnly("persons", persons.describe(), "wearers of person nodes, each watched on "
                            + "their own"));
        }
    }
}
