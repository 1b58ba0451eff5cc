package org.tinysep.houseinformation.internal;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlElementWrapper;
import jakarta.xml.bind.annotation.XmlType;
import java.util.ArrayList;
import java.util.List;

/** JAXB binding of one {@code <ROOM>} (thesis Figure 3.7). */
@XmlAccessorType(XmlAccessType.FIELD)
@XmlType(propOrder = {"uid", "name", "type", "neighbours"})
public class RoomXml {

    @XmlElement(name = "UID")
    public String uid;
    @XmlElement(name = "NAME")
    public String name;
    @XmlElement(name = "TYPE")
    public String type;
    @XmlElementWrapper(name = "NEIGHBORS")
    @XmlElement(name = "ROOM_UID")
    public List<String> neighbours = new ArrayList<>();
}
