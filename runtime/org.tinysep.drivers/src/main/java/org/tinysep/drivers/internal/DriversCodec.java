package org.tinysep.drivers.internal;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.Marshaller;
import jakarta.xml.bind.Unmarshaller;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import org.xml.sax.SAXParseException;

/**
 * Reads and writes {@code drivers.xml} with JAXB. Inside OSGi the JAXB implementation is found through this bundle's
 * class loader (thread context class loader around every JAXB call). DTDs and external entities are refused; an
 * entry without {@code FILE_PATH}, or two entries with one symbolic name, make the whole file malformed.
 */
final class DriversCodec {

    private final JAXBContext jaxb;

    DriversCodec() {
        ClassLoader old = swapLoader();
        try {
            jaxb = JAXBContext.newInstance(DriversListXml.class);
        } catch (JAXBException | LinkageError e) {
            throw new IllegalStateException("JAXB is not available: " + e, e);
        } finally {
            Thread.currentThread().setContextClassLoader(old);
        }
    }

    /** @return the entries of {@code xml}, in file order; {@code source} names the file in messages */
    List<DriverEntry> read(byte[] xml, String source) throws MalformedDriversException {
        DriversListXml root;
        ClassLoader old = swapLoader();
        try {
            XMLInputFactory f = XMLInputFactory.newFactory();
            f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
            f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
            XMLStreamReader reader = f.createXMLStreamReader(new ByteArrayInputStream(xml));
            Unmarshaller u = jaxb.createUnmarshaller();
            u.setEventHandler(event -> false); // any problem aborts: a half-read list is never applied
            root = u.unmarshal(reader, DriversListXml.class).getValue();
        } catch (XMLStreamException | JAXBException | RuntimeException e) {
            throw new MalformedDriversException(source + ": bad XML: " + reason(e), e);
        } finally {
            Thread.currentThread().setContextClassLoader(old);
        }
        List<DriverEntry> entries = new ArrayList<>();
        Set<String> keys = new HashSet<>();
        int n = 0;
        for (DriverXml d : root == null || root.drivers == null ? List.<DriverXml>of() : root.drivers) {
            n++;
            DriverEntry e = new DriverEntry(d.filePath, d.fullName, d.enabled == null || d.enabled, d.status);
            if (e.location().isEmpty()) {
                throw new MalformedDriversException(source + ": DRIVER #" + n + " has no FILE_PATH", null);
            }
            if (!keys.add(e.key())) {
                throw new MalformedDriversException(source + ": DRIVER #" + n + " repeats " + e.key(), null);
            }
            entries.add(e);
        }
        return entries;
    }

    /** @return the entries as UTF-8 XML; equal lists give equal bytes */
    byte[] write(List<DriverEntry> entries) {
        DriversListXml root = new DriversListXml();
        for (DriverEntry e : entries) {
            DriverXml d = new DriverXml();
            d.filePath = e.location();
            d.fullName = e.symbolicName().isEmpty() ? null : e.symbolicName();
            d.enabled = e.enabled();
            d.status = e.status().isEmpty() ? null : e.status();
            root.drivers.add(d);
        }
        ClassLoader old = swapLoader();
        try {
            Marshaller m = jaxb.createMarshaller();
            m.setProperty(Marshaller.JAXB_FORMATTED_OUTPUT, true);
            m.setProperty(Marshaller.JAXB_ENCODING, StandardCharsets.UTF_8.name());
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            m.marshal(root, out);
            return out.toByteArray();
        } catch (JAXBException e) {
            throw new IllegalStateException("cannot write the drivers list as XML: " + e, e);
        } finally {
            Thread.currentThread().setContextClassLoader(old);
        }
    }

    /** @return the parser's message with its line and column, on one line */
    private static String reason(Throwable failure) {
        String reason = failure.getMessage() == null ? failure.toString() : failure.getMessage();
        for (Throwable t = failure; t != null; t = t instanceof JAXBException j && j.getLinkedException() != null
                ? j.getLinkedException() : t.getCause() == t ? null : t.getCause()) {
            if (t instanceof SAXParseException x) {
                reason = "line " + x.getLineNumber() + ", column " + x.getColumnNumber() + ": " + x.getMessage();
            } else if (t instanceof XMLStreamException x) {
                String msg = x.getMessage() == null ? "" : x.getMessage();
                int m = msg.indexOf("Message: ");
                reason = (x.getLocation() == null ? "" : "line " + x.getLocation().getLineNumber() + ", column "
                        + x.getLocation().getColumnNumber() + ": ") + (m >= 0 ? msg.substring(m + 9) : msg);
            }
        }
        return reason.replaceAll("\\s+", " ").strip();
    }

    private static ClassLoader swapLoader() {
        ClassLoader old = Thread.currentThread().getContextClassLoader();
        Thread.currentThread().setContextClassLoader(DriversCodec.class.getClassLoader());
        return old;
    }
}
