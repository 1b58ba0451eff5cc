package org.tinysep.runtime.internal.backup;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.Marshaller;
import jakarta.xml.bind.Unmarshaller;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamReader;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;

/**
 * Converts backups to and from XML. Files are written by {@link BackupXmlWriter} and files of that shape read by
 * {@link BackupXmlReader}; JAXB reads any other shape, and its context is made only when such a file comes (or a test
 * asks), so an ordinary start loads none of JAXB's classes (issue 29: start time and idle memory). Inside OSGi the
 * JAXB implementation is found through this bundle's class loader (thread context class loader around the JAXB
 * calls). DTDs and external entities are refused; a file that is not a complete, valid backup is rejected with a
 * {@link BadBackupException}.
 */
final class BackupCodec {

    /** Made on first use: {@link #jaxb()}. */
    private volatile JAXBContext jaxb;
    /**
     * One StAX factory for every read (DTDs and external entities off): looking one up per file cost a service
     * loader search each, with 20,000 files read at start.
     */
    private final XMLInputFactory xmlInput;

    BackupCodec() {
        xmlInput = XMLInputFactory.newFactory();
        xmlInput.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        xmlInput.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
    }

    /** @return JAXB's context for {@link BackupXml}, made on the first call */
    private JAXBContext jaxb() {
        JAXBContext c = jaxb;
        if (c == null) {
            synchronized (this) {
                c = jaxb;
                if (c == null) {
                    try {
                        c = withBundleLoader(() -> JAXBContext.newInstance(BackupXml.class));
                    } catch (Exception | LinkageError e) {
                        throw new IllegalStateException("JAXB is not available: " + e, e);
                    }
                    jaxb = c;
                }
            }
        }
        return c;
    }

    /** @return whether JAXB's context has been made (tests: an ordinary start and restore make none) */
    boolean jaxbMade() {
        return jaxb != null;
    }

    /** @return the backup's file content (written without JAXB: {@link BackupXmlWriter}, the same bytes) */
    byte[] write(ComponentBackup b) {
        return BackupXmlWriter.write(b);
    }

    /** @return the file content as JAXB writes it (the reference for {@link BackupXmlWriter}; tests) */
    byte[] writeWithJaxb(ComponentBackup b) {
        BackupXml x = new BackupXml();
        x.kind = b.kind().name();
        x.uid = b.uid();
        x.driverUid = b.driverUid();
        x.driverName = b.driverName();
        x.type = b.type();
        x.name = b.name();
        x.savedAt = b.savedAt().toString();
        x.nodeAddress = b.nodeAddress();
        x.nodeTypes.addAll(b.nodeTypes());
        x.lastSeen = b.lastSeen() == null ? null : b.lastSeen().toString();
        b.parameters().forEach((k, v) -> x.parameters.add(new BackupXml.Entry(k, v)));
        b.state().forEach((k, v) -> x.state.add(new BackupXml.Entry(k, v)));
        try {
            return withBundleLoader(() -> {
                Marshaller m = jaxb().createMarshaller();
                m.setProperty(Marshaller.JAXB_FORMATTED_OUTPUT, true);
                m.setProperty(Marshaller.JAXB_ENCODING, "UTF-8");
                ByteArrayOutputStream out = new ByteArrayOutputStream();
                m.marshal(x, out);
                return out.toByteArray();
            });
        } catch (Exception e) {
            throw new IllegalStateException("cannot write the backup of " + b.uid() + ": " + e, e);
        }
    }

    /**
     * @return the backup in the file; a file in the shape this codec writes is read without JAXB
     *         ({@link BackupXmlReader}), any other by JAXB, which rejects what is not a backup
     */
    ComponentBackup read(byte[] xml) throws BadBackupException {
        BackupXml fast = BackupXmlReader.read(xml);
        return fast != null ? toBackup(fast) : readWithJaxb(xml);
    }

    /** @return the backup in the file, read by JAXB (any shape it accepts; tests compare both readers) */
    ComponentBackup readWithJaxb(byte[] xml) throws BadBackupException {
        BackupXml x;
        try {
            XMLStreamReader reader;
            synchronized (xmlInput) {
                reader = xmlInput.createXMLStreamReader(new ByteArrayInputStream(xml));
            }
            x = withBundleLoader(() -> {
                Unmarshaller u = jaxb().createUnmarshaller();
                u.setEventHandler(event -> false); // any error ends the read
                return u.unmarshal(reader, BackupXml.class).getValue();
            });
        } catch (Exception e) {
            throw new BadBackupException("not a readable backup: " + rootCause(e));
        }
        return toBackup(x);
    }

    private static ComponentBackup toBackup(BackupXml x) throws BadBackupException {
        if (x == null || blank(x.uid) || blank(x.kind) || blank(x.savedAt)) {
            throw new BadBackupException("incomplete backup: uid, kind and savedAt are required");
        }
        try {
            return new ComponentBackup(x.uid.strip(), ComponentKind.valueOf(x.kind.strip()), x.driverUid,
                    x.driverName, x.type, x.name, map(x.parameters), x.nodeAddress,
                    x.nodeTypes == null ? List.of() : x.nodeTypes,
                    blank(x.lastSeen) ? null : Instant.parse(x.lastSeen.strip()), map(x.state),
                    Instant.parse(x.savedAt.strip()));
        } catch (IllegalArgumentException | DateTimeParseException | NullPointerException e) {
            throw new BadBackupException("invalid backup: " + e.getMessage());
        }
    }

    private static Map<String, String> map(List<BackupXml.Entry> entries) {
        Map<String, String> m = new LinkedHashMap<>();
        if (entries != null) {
            for (BackupXml.Entry e : entries) {
                m.put(e.key, e.value == null ? "" : e.value);
            }
        }
        return m;
    }

    private static boolean blank(String s) {
        return s == null || s.isBlank();
    }

    private static String rootCause(Throwable e) {
        Throwable t = e;
        while (t.getCause() != null && t.getCause() != t) {
            t = t.getCause();
        }
        String m = t.getMessage();
        return (m == null ? t.getClass().getSimpleName() : m).replaceAll("\\s+", " ");
    }

    private static <T> T withBundleLoader(Callable<T> work) throws Exception {
        Thread thread = Thread.currentThread();
        ClassLoader previous = thread.getContextClassLoader();
        thread.setContextClassLoader(BackupCodec.class.getClassLoader());
        try {
            return work.call();
        } finally {
            thread.setContextClassLoader(previous);
        }
    }
}
