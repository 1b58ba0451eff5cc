package org.tinysep.runtime.internal.backup;

import java.io.InputStream;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Properties;
import java.util.regex.Pattern;
import javax.xml.XMLConstants;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamReader;
import javax.xml.transform.stax.StAXSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import javax.xml.validation.Validator;
import org.xml.sax.SAXParseException;

/**
 * Checks every staged file of an archive before anything is replaced (docs/backup.md): each backup file parses as a
 * backup; {@code house.xml} and {@code drivers.xml} are valid against the schemas of the files House Information and
 * the drivers list write ({@code house.xsd}, {@code drivers.xsd}: right root, known elements only, unique keys);
 * a drivers-list {@code FILE_PATH} that is a URL is {@code file:} or {@code https:}; each cfg is one TinySEP owns
 * ({@link OwnedConfig}) and loads as properties; the backup key is never taken from an archive. DTDs and external
 * entities are refused everywhere.
 */
final class ArchiveValidator {

    private static final Pattern URL = Pattern.compile("([a-zA-Z][a-zA-Z0-9+.-]+):.*", Pattern.DOTALL);
    private static volatile Schema house;
    private static volatile Schema drivers;

    private ArchiveValidator() {
    }

    /** @return one line per problem, naming the entry; empty when every file is good */
    static List<String> problems(Path staging, List<String> names, BackupCodec codec, boolean needBackups) {
        List<String> out = new ArrayList<>();
        for (String name : names) {
            String problem;
            try {
                problem = check(name, Files.readAllBytes(staging.resolve(name)), codec);
            } catch (Exception e) {
                problem = "unreadable: " + oneLine(e.getMessage());
            }
            if (problem != null) {
                out.add(name + ": " + problem);
            }
        }
        if (needBackups && names.stream().noneMatch(n -> n.startsWith("backup/"))) {
            out.add("no backup/ files: not a TinySEP configuration archive");
        }
        return out;
    }

    private static String check(String name, byte[] bytes, BackupCodec codec) throws Exception {
        if (name.startsWith("backup/")) {
            try {
                codec.read(bytes);
                return null;
            } catch (BadBackupException e) {
                return e.getMessage();
            }
        } else if (name.equals("house.xml")) {
            return validate(houseSchema(), bytes, "a house plan (HOUSE_ROOMS of ROOMs)");
        } else if (name.equals("drivers.xml")) {
            String problem = validate(driversSchema(), bytes, "a drivers list (DRIVERS_LIST of DRIVERs)");
            return problem != null ? problem : schemes(bytes);
        } else if (name.startsWith("etc/")) {
            String file = name.substring(4);
            if (!OwnedConfig.owned(file)) {
                return "not a configuration TinySEP owns; a restore changes only org.tinysep.* PIDs of the shipped "
                        + "bundles (docs/backup.md), never FileInstall's or another bundle's";
            }
            try (Reader r = new java.io.StringReader(new String(bytes, StandardCharsets.UTF_8))) {
                new Properties().load(r);
            } catch (IllegalArgumentException e) {
                return "malformed: " + oneLine(e.getMessage());
            }
            return null;
        } else if (name.equals("secrets/" + ArchiveSignature.KEY_FILE)) {
            return "the backup key is never taken from an archive";
        }
        return null;
    }

    /** @return null when {@code xml} is valid against {@code schema}; else where and why it is not */
    private static String validate(Schema schema, byte[] xml, String what) throws Exception {
        Validator v = schema.newValidator();
        v.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        v.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        try (InputStream in = new java.io.ByteArrayInputStream(xml)) {
            v.validate(new StAXSource(reader(in)));
            return null;
        } catch (SAXParseException e) {
            return "not " + what + ": line " + e.getLineNumber() + ", column " + e.getColumnNumber() + ": "
                    + oneLine(e.getMessage());
        } catch (Exception e) {
            return "not " + what + ": " + oneLine(e.getMessage());
        }
    }

    /** @return null when every URL FILE_PATH is file: or https:; else the first that is not */
    private static String schemes(byte[] xml) throws Exception {
        XMLStreamReader r = reader(new java.io.ByteArrayInputStream(xml));
        int n = 0;
        while (r.hasNext()) {
            if (r.next() == XMLStreamConstants.START_ELEMENT && r.getLocalName().equals("FILE_PATH")) {
                n++;
                String problem = locationProblem(r.getElementText().strip());
                if (problem != null) {
                    return "DRIVER #" + n + ": " + problem;
                }
            }
        }
        return null;
    }

    /** @return null when a drivers-list FILE_PATH may be used; else why not (docs/runtime-changes.md) */
    static String locationProblem(String filePath) {
        var m = URL.matcher(filePath);
        if (!m.matches()) {
            return null; // a path
        }
        String scheme = m.group(1).toLowerCase(Locale.ROOT);
        return scheme.equals("file") || scheme.equals("https") ? null
                : "FILE_PATH " + filePath + " uses " + scheme + ": — only file: and https: URLs are accepted";
    }

    private static XMLStreamReader reader(InputStream in) throws Exception {
        XMLInputFactory f = XMLInputFactory.newDefaultFactory();
        f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        return f.createXMLStreamReader(in);
    }

    private static Schema houseSchema() throws Exception {
        if (house == null) {
            house = schema("house.xsd");
        }
        return house;
    }

    private static Schema driversSchema() throws Exception {
        if (drivers == null) {
            drivers = schema("drivers.xsd");
        }
        return drivers;
    }

    private static Schema schema(String resource) throws Exception {
        SchemaFactory f = SchemaFactory.newDefaultInstance();
        f.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        f.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        try (InputStream in = ArchiveValidator.class.getResourceAsStream(resource)) {
            return f.newSchema(new javax.xml.transform.stream.StreamSource(in));
        }
    }

    private static String oneLine(String s) {
        return String.valueOf(s).replaceAll("\\s+", " ").strip();
    }
}
