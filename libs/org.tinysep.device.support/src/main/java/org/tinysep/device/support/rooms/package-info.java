/**
 * Rooms and where devices are: {@link Rooms} (a user's room reference resolved), {@link RoomDirectory} (House
 * Information's rooms), {@link Placements} and {@link TrackedPlacements} (the devices' rooms and names) and
 * {@link UnmonitoredRooms} (the rooms Sensor Health says cannot be heard now).
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.1.0")
package org.tinysep.device.support.rooms;

import org.osgi.annotation.versioning.Version;
