package org.tinysep.drivers.internal;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlRootElement;
import java.util.ArrayList;
import java.util.List;

/** JAXB binding of the drivers file's root element (thesis Figure 3.5). */
@XmlRootElement(name = "DRIVERS_LIST")
@XmlAccessorType(XmlAccessType.FIELD)
public class DriversListXml {

    @XmlElement(name = "DRIVER")
    public List<DriverXml> drivers = new ArrayList<>();
}
