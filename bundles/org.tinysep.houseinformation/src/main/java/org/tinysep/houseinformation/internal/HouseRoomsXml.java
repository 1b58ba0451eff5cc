package org.tinysep.houseinformation.internal;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlRootElement;
import java.util.ArrayList;
import java.util.List;

/** JAXB binding of the house file's root element (thesis Figure 3.7). */
@XmlRootElement(name = "HOUSE_ROOMS")
@XmlAccessorType(XmlAccessType.FIELD)
public class HouseRoomsXml {

    @XmlElement(name = "ROOM")
    public List<RoomXml> rooms = new ArrayList<>();
}
