package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertListener;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.InactivityAlert;

/**
 * Issue 25, item 2: an alert handed over once is not handed over twice, unless the alert service no longer has it
 * open or acknowledged (it was closed while the person stayed quiet): then it is raised again, not silently lost.
 */
class HelpCallTest {

    private static final Instant T = Instant.parse("2026-11-25T09:12:00Z");
    private static final InactivityAlert ALERT = new InactivityAlert("r1", "Bathroom", "movement in Bathroom", T,
            T.plusSeconds(2700), "");

    /** An alert service that keeps what it is given; {@link #close} sets an alert's state. */
    private static final class Service implements AlertService {
        final List<Alert> alerts = new ArrayList<>();

        @Override
        public Alert raise(AlertRequest r) {
            Optional<Alert> same = open().stream().filter(a -> a.raisedAt().equals(r.raisedAt())).findFirst();
            if (same.isPresent()) {
                return same.get();
            }
            Alert a = new Alert(Integer.toString(alerts.size() + 1), r.kind(), r.source(), r.roomUid(), r.roomName(),
                    r.raisedAt(), r.subject(), r.text(), AlertState.OPEN, 1, null, null, List.of());
            alerts.add(a);
            return a;
        }

        void close(int index, AlertState state) {
            Alert a = alerts.get(index);
            alerts.set(index, new Alert(a.id(), a.kind(), a.source(), a.roomUid(), a.roomName(), a.raisedAt(),
                    a.subject(), a.text(), state, 1, T.plusSeconds(3000), "someone", a.notifications()));
        }

        @Override
        public Alert acknowledge(String id, String by) {
            throw new UnsupportedOperationException();
        }

        @Override
        public List<Alert> clear(String source, String why) {
            throw new UnsupportedOperationException();
        }

        @Override
        public List<Alert> open() {
            return alerts.stream().filter(Alert::isOpen).toList();
        }

        @Override
        public List<Alert> recent(int max) {
            return List.copyOf(alerts);
        }

        @Override
        public Optional<Alert> alert(String id) {
            return alerts.stream().filter(a -> a.id().equals(id)).findFirst();
        }

        @Override
        public Connection connect(AlertListener listener) {
            throw new UnsupportedOperationException();
        }
    }

    private final Service service = new Service();
    private final HelpCall help = new HelpCall(new AlertMail(ZoneOffset.UTC, List::of), new HelpCall.AlertDesk() {
        @Override
        public <X> Optional<X> use(Function<AlertService, X> use) {
            return Optional.ofNullable(use.apply(service));
        }
    });

    @Test
    void anOpenAlertIsNotHandedOverTwice() {
        assertEquals(HelpCall.Outcome.HANDED_TO_ALERT_SERVICE, help.call(ALERT));
        assertEquals(HelpCall.Outcome.ALREADY_HANDED_OVER, help.call(ALERT));
        assertEquals(1, service.alerts.size());
    }

    @Test
    void anAcknowledgedAlertIsNotRaisedAgain() {
        help.call(ALERT);
        service.close(0, AlertState.ACKNOWLEDGED);
        assertEquals(HelpCall.Outcome.ALREADY_HANDED_OVER, help.call(ALERT));
        assertEquals(1, service.alerts.size());
    }

    @Test
    void anAlertClosedWhileThePersonStaysQuietIsRaisedAgain() {
        help.call(ALERT);
        service.close(0, AlertState.CLEARED);
        assertEquals(HelpCall.Outcome.RAISED_AGAIN, help.call(ALERT));
        assertEquals(2, service.alerts.size());
        assertEquals(AlertState.OPEN, service.alerts.get(1).state());
        assertEquals(HelpCall.Outcome.ALREADY_HANDED_OVER, help.call(ALERT), "then open: once is enough");
    }

    @Test
    void afterARestartAnAlertTheServiceNoLongerHasOpenIsRaisedAgain() {
        help.handedOverDue(ALERT.raisedAt()); // from the backup: handed over before the restart
        service.raise(new AlertRequest(org.tinysep.api.alert.AlertKind.INACTIVITY, HelpCall.SOURCE, "r1", "Bathroom",
                ALERT.raisedAt(), "s", "t"));
        service.close(0, AlertState.CLEARED); // the old side effect: "the flat became unoccupied" with nobody gone
        assertEquals(HelpCall.Outcome.RAISED_AGAIN, help.call(ALERT));
        assertEquals(AlertState.OPEN, service.alerts.get(1).state());
    }
}
