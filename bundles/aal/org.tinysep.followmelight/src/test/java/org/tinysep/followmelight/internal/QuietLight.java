package org.tinysep.followmelight.internal;

import java.util.Optional;
import org.tinysep.api.actuator.SimpleLightListener;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.device.support.testing.FakeProvider;

/** A simple light that counts what it is asked and never reports: for cost tests and the harness (no journal). */
final class QuietLight extends FakeProvider<SimpleLightListener> implements SimpleLightProvider {

    int switchedOn;
    int switchedOff;

    QuietLight(String uid) {
        super(uid);
    }

    @Override
    public void switchLight(boolean on) {
        if (on) {
            switchedOn++;
        } else {
            switchedOff++;
        }
    }

    @Override
    public Optional<Boolean> isOn() {
        return Optional.empty();
    }
}
