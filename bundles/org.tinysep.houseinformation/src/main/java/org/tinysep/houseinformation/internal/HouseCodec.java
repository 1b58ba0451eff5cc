package org.tinysep.houseinformation.internal;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.Marshaller;
import jakarta.xml.bind.Unmarshaller;
import jakarta.xml.bind.ValidationEventLocator;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import org.tinysep.api.service.Room;

/**
 * Reads and writes the house file (thesis Figure 3.7) with JAXB. Inside OSGi the JAXB implementation is found
 * through this bundle's class loader (thread context class loader around the JAXB calls; the bundle imports
 * {@code org.glassfish.jaxb.runtime.v2} optionally). DTDs and external entities are refused.
 */
final class HouseCodec {

    private final JAXBContext jaxb;

    HouseCodec() {
        try {
            jaxb = withBundleLoader(() -> {
                try {
                    return JAXBContext.newInstance(HouseRoomsXml.class);
                } catch (JAXBException e) {
                    throw new IllegalStateException("JAXB is not available: " + e, e);
                }
            });
        } catch (LinkageError e) {
            throw new IllegalStateException("JAXB is not available: " + e, e);
        }
    }

    /** @return the plan in {@code xml}; {@code source} names the file in messages */
    HousePlan read(byte[] xml, String source) throws MalformedHouseException {
        AtomicReference<String> where = new AtomicReference<>("");
        HouseRoomsXml root;
        try {
            XMLInputFactory f = XMLInputFactory.newFactory();
            f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
            f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
            XMLStreamReader reader = f.createXMLStreamReader(new ByteArrayInputStream(xml));
            root = withBundleLoader(() -> {
                try {
                    Unmarshaller u = jaxb.createUnmarshaller();
                    u.setEventHandler(event -> {
                        ValidationEventLocator l = event.getLocator();
                        if (l != null && l.getLineNumber() > 0) {
                            where.set(" at line " + l.getLineNumber() + ", column " + l.getColumnNumber());
                        }
                        return false;
                    });
                    return u.unmarshal(reader, HouseRoomsXml.class).getValue();
                } catch (JAXBException e) {
                    throw new BadXml(e);
                }
            });
        } catch (XMLStreamException e) {
            throw new MalformedHouseException(source + ": not XML: " + e.getMessage(), e);
        } catch (BadXml e) {
            throw malformed(source, where.get(), e.getCause());
        }
        if (root == null || root.rooms == null) {
            return HousePlan.EMPTY;
        }
        List<Room> rooms = new ArrayList<>();
        for (RoomXml r : root.rooms) {
            rooms.add(new Room(text(r.uid), text(r.name), text(r.type),
                    r.neighbours == null ? Set.of() : new LinkedHashSet<>(r.neighbours.stream().map(HouseCodec::text)
                            .toList())));
        }
        try {
            return HousePlan.of(rooms);
        } catch (IllegalArgumentException e) {
            throw new MalformedHouseException(source + ": " + e.getMessage(), e);
        }
    }

    /** @return the plan as UTF-8 XML; equal plans give equal bytes */
    byte[] write(HousePlan plan) {
        HouseRoomsXml root = new HouseRoomsXml();
        for (Room r : plan.rooms()) {
            RoomXml x = new RoomXml();
            x.uid = r.uid();
            x.name = r.name();
            x.type = r.type();
            x.neighbours = new ArrayList<>(plan.orderedNeighbours(r));
            root.rooms.add(x);
        }
        return withBundleLoader(() -> {
            try {
                Marshaller m = jaxb.createMarshaller();
                m.setProperty(Marshaller.JAXB_FORMATTED_OUTPUT, true);
                m.setProperty(Marshaller.JAXB_ENCODING, StandardCharsets.UTF_8.name());
                ByteArrayOutputStream out = new ByteArrayOutputStream();
                m.marshal(root, out);
                return out.toByteArray();
            } catch (JAXBException e) {
                throw new IllegalStateException("cannot write the house as XML: " + e, e);
            }
        });
    }

    /** @return one line naming the file, the line and column when known, and the parser's reason */
    private static MalformedHouseException malformed(String source, String where, Throwable failure) {
        String reason = failure.toString();
        for (Throwable t = failure; t != null; t = t.getCause()) {
            if (t instanceof XMLStreamException x) {
                if (where.isEmpty() && x.getLocation() != null && x.getLocation().getLineNumber() > 0) {
                    where = " at line " + x.getLocation().getLineNumber() + ", column "
                            + x.getLocation().getColumnNumber();
                }
                reason = x.getMessage();
            } else if (t.getMessage() != null && t == failure) {
                reason = t.getMessage();
            }
        }
        int m = reason == null ? -1 : reason.indexOf("Message: ");
        reason = reason == null ? failure.toString() : m >= 0 ? reason.substring(m + 9) : reason;
        return new MalformedHouseException(source + where + ": bad XML: " + reason.replaceAll("\\s+", " ").strip(),
                failure);
    }

    private static String text(String s) {
        return s == null ? "" : s.strip();
    }

    private static <T> T withBundleLoader(Supplier<T> work) {
        Thread t = Thread.currentThread();
        ClassLoader old = t.getContextClassLoader();
        t.setContextClassLoader(HouseCodec.class.getClassLoader());
        try {
            return work.get();
        } finally {
            t.setContextClassLoader(old);
        }
    }

    /** Carries a JAXB failure out of a lambda. */
    private static final class BadXml extends RuntimeException {
        private static final long serialVersionUID = 1L;

        BadXml(JAXBException cause) {
            super(cause);
        }
    }
}
