/**
 * The house file ({@code house.xml}, thesis Figure 3.7: {@code <HOUSE_ROOMS><ROOM><UID/><NAME/><TYPE/><NEIGHBORS>
 * <ROOM_UID/>...}) read and written once: {@link org.tinysep.house.codec.HouseXml} turns the bytes into
 * {@link org.tinysep.house.codec.HouseRooms} / {@link org.tinysep.house.codec.HouseRoom} records and back, with the
 * JDK's StAX (no JAXB). Errors name the source, line and column and what was expected; a DOCTYPE (and so any entity,
 * internal or external) is refused.
 * <p>
 * Not exported at run time: House Information and the simulator copy the package in with bnd's
 * {@code -conditionalpackage: org.tinysep.house.codec}; the evaluation has it on its class path.
 */
@Version("1.0.0")
package org.tinysep.house.codec;

import org.osgi.annotation.versioning.Version;
