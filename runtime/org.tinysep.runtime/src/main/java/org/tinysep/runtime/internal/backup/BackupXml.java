package org.tinysep.runtime.internal.backup;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlElementWrapper;
import jakarta.xml.bind.annotation.XmlRootElement;
import jakarta.xml.bind.annotation.XmlValue;
import java.util.ArrayList;
import java.util.List;

/** The XML shape of one backup file (example in docs/backup.md). */
@XmlRootElement(name = "backup")
@XmlAccessorType(XmlAccessType.FIELD)
final class BackupXml {

    @XmlAttribute(name = "version")
    int version = 1;
    @XmlAttribute(name = "kind")
    String kind;
    @XmlElement(name = "uid")
    String uid;
    @XmlElement(name = "driverUid")
    String driverUid;
    @XmlElement(name = "driverName")
    String driverName;
    @XmlElement(name = "type")
    String type;
    @XmlElement(name = "name")
    String name;
    @XmlElement(name = "savedAt")
    String savedAt;
    @XmlElement(name = "nodeAddress")
    String nodeAddress;
    @XmlElementWrapper(name = "nodeTypes")
    @XmlElement(name = "nodeType")
    List<String> nodeTypes = new ArrayList<>();
    @XmlElement(name = "lastSeen")
    String lastSeen;
    @XmlElementWrapper(name = "parameters")
    @XmlElement(name = "parameter")
    List<Entry> parameters = new ArrayList<>();
    @XmlElementWrapper(name = "state")
    @XmlElement(name = "value")
    List<Entry> state = new ArrayList<>();

    /** One key and its value: {@code <parameter key="room">…</parameter>}. */
    @XmlAccessorType(XmlAccessType.FIELD)
    static final class Entry {
        @XmlAttribute(name = "key", required = true)
        String key;
        @XmlValue
        String value;

        Entry() {
        }

        Entry(String key, String value) {
            this.key = key;
            this.value = value;
        }
    }
}
