package org.tinysep.device.support.testing;

import java.time.Instant;
import java.util.List;
import org.tinysep.api.service.FlatOccupancyListener;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;

/** A Flat Occupancy for unit tests: {@link #change} sets the decision and tells the listeners. */
public class FakeFlat extends FakeProvider<FlatOccupancyListener> implements FlatOccupancyProvider {

    public Occupancy occupancy;
    public Instant since;

    public FakeFlat(String uid, Occupancy occupancy, Instant since) {
        super(uid);
        this.occupancy = occupancy;
        this.since = since;
    }

    public void change(Occupancy o, Instant at) {
        occupancy = o;
        since = at;
        List.copyOf(listeners).forEach(l -> l.occupancyChanged(this, o, at));
    }

    @Override
    public Occupancy occupancy() {
        return occupancy;
    }

    @Override
    public Instant since() {
        return since;
    }
}
