package org.tinysep.api.service;

import java.time.Instant;
import java.util.List;
import org.osgi.annotation.versioning.ConsumerType;

@ConsumerType
public interface HouseInformationListener {

    /** Called after every change with the whole new plan. */
    void houseChanged(HouseInformationProvider source, List<Room> rooms, Instant at);
}
