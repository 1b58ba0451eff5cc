package org.tinysep.inactivity.internal.learn;

import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;

/** Builds a home's history day by day for the tests (UTC, Monday 2026-11-02 is day 0). */
final class History {

    static final LocalDate MONDAY = LocalDate.of(2026, 11, 2);
    private final List<Sighting> sightings = new ArrayList<>();

    static Instant at(int day, String hhmm) {
        return MONDAY.plusDays(day).atTime(LocalTime.parse(hhmm)).toInstant(ZoneOffset.UTC);
    }

    History in(String room, int day, String hhmm) {
        String type = room.equals("Bed") ? "Bedroom" : room;
        sightings.add(new Sighting(at(day, hhmm), room, room, type, false));
        return this;
    }

    History inBed(int day, String hhmm) {
        sightings.add(new Sighting(at(day, hhmm), "Bed", "Bed", "Bedroom", true));
        return this;
    }

    List<Sighting> sightings() {
        return sightings.stream().sorted(java.util.Comparator.comparing(Sighting::at)).toList();
    }
}
