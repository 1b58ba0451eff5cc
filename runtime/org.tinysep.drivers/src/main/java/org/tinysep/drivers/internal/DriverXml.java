package org.tinysep.drivers.internal;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlType;

/**
 * JAXB binding of one {@code <DRIVER>} (thesis Figure 3.5): {@code FILE_PATH} and {@code FULL_NAME} as in the thesis
 * (here the bundle's location and Bundle-SymbolicName), plus {@code ENABLED} (absent = true) and {@code STATUS},
 * which the platform maintains.
 */
@XmlAccessorType(XmlAccessType.FIELD)
@XmlType(propOrder = {"filePath", "fullName", "enabled", "status"})
public class DriverXml {

    @XmlElement(name = "FILE_PATH")
    public String filePath;
    @XmlElement(name = "FULL_NAME")
    public String fullName;
    @XmlElement(name = "ENABLED")
    public Boolean enabled;
    @XmlElement(name = "STATUS")
    public String status;
}
