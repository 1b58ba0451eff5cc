package org.tinysep.runtime.internal.backup;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Set;

/**
 * Reads a backup file in the exact shape {@link BackupXmlWriter} writes, without a StAX reader or JAXB: a start
 * reads every backup file (20,000 at once for a large platform), and JAXB's read was most of that (JFR, issue 29).
 * Anything else — another declaration, a DTD, a comment, an unknown element or attribute, an entity it does not
 * know, a character XML forbids, bytes that are not UTF-8 — is declined ({@code null}) and the codec reads the file
 * with JAXB as before, so every file outside that shape (a damaged one included) meets exactly the checks it met
 * before; {@code BackupXmlReaderTest} compares both readers on random and damaged files.
 */
final class BackupXmlReader {

    private static final String DECLARATION = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>";
    private static final Set<String> TEXTS = Set.of("uid", "driverUid", "driverName", "type", "name", "savedAt",
            "nodeAddress", "lastSeen");

    /** Thrown inside: the file is outside the shape this reader takes. */
    private static final class Decline extends Exception {
        Decline() {
            super(null, null, false, false);
        }
    }

    private final String s;
    private int at;

    private BackupXmlReader(String s) {
        this.s = s;
    }

    /** @return the file's content as JAXB would read it, or null when the file is not in the writer's shape */
    static BackupXml read(byte[] bytes) {
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            return null;
        }
        try {
            return new BackupXmlReader(text).backup();
        } catch (Decline e) {
            return null;
        }
    }

    private BackupXml backup() throws Decline {
        expect(DECLARATION);
        space();
        expect("<backup");
        BackupXml x = new BackupXml();
        boolean version = false;
        boolean kind = false;
        while (true) {
            boolean spaced = space();
            if (take(">")) {
                break;
            }
            if (!spaced) {
                throw new Decline(); // an attribute needs a space before it
            }
            String name = name();
            String value = attributeValue();
            if (name.equals("version") && !version && value.matches("[0-9]{1,9}")) {
                x.version = Integer.parseInt(value);
                version = true;
            } else if (name.equals("kind") && !kind) {
                x.kind = value;
                kind = true;
            } else {
                throw new Decline();
            }
        }
        Set<String> seen = new java.util.HashSet<>();
        while (true) {
            space();
            if (take("</backup>")) {
                break;
            }
            expect("<");
            String tag = name();
            if (!seen.add(tag)) {
                throw new Decline(); // JAXB's rule for a repeated element is not one to copy
            }
            if (TEXTS.contains(tag)) {
                set(x, tag, textElement(tag));
            } else if (tag.equals("nodeTypes")) {
                list(tag, "nodeType", x.nodeTypes, null);
            } else if (tag.equals("parameters")) {
                list(tag, "parameter", null, x.parameters);
            } else if (tag.equals("state")) {
                list(tag, "value", null, x.state);
            } else {
                throw new Decline();
            }
        }
        space();
        if (at != s.length()) {
            throw new Decline();
        }
        return x;
    }

    private static void set(BackupXml x, String tag, String v) {
        switch (tag) {
            case "uid" -> x.uid = v;
            case "driverUid" -> x.driverUid = v;
            case "driverName" -> x.driverName = v;
            case "type" -> x.type = v;
            case "name" -> x.name = v;
            case "savedAt" -> x.savedAt = v;
            case "nodeAddress" -> x.nodeAddress = v;
            default -> x.lastSeen = v;
        }
    }

    /** After {@code <tag}: {@code >text</tag>} or {@code />} (empty text). */
    private String textElement(String tag) throws Decline {
        if (take("/>")) {
            return "";
        }
        expect(">");
        String v = text();
        expect("</" + tag + ">");
        return v;
    }

    /** After {@code <wrapper}: {@code />} or {@code >} items {@code </wrapper>}; items are texts or key entries. */
    private void list(String wrapper, String item, List<String> texts, List<BackupXml.Entry> entries)
            throws Decline {
        if (take("/>")) {
            return;
        }
        expect(">");
        while (true) {
            space();
            if (take("</" + wrapper + ">")) {
                return;
            }
            expect("<" + item);
            if (texts != null) {
                texts.add(textElement(item));
                continue;
            }
            if (!space() || !name().equals("key")) {
                throw new Decline();
            }
            String key = attributeValue();
            space();
            String value = take("/>") ? null : textAfterOpen(item);
            entries.add(new BackupXml.Entry(key, value));
        }
    }

    private String textAfterOpen(String tag) throws Decline {
        expect(">");
        String v = text();
        expect("</" + tag + ">");
        return v;
    }

    private String name() throws Decline {
        int from = at;
        while (at < s.length() && (Character.isLetterOrDigit(s.charAt(at)) || s.charAt(at) == '_')) {
            at++;
        }
        if (at == from) {
            throw new Decline();
        }
        return s.substring(from, at);
    }

    /** {@code ="value"} (or single quotes); raw tab, line feed and carriage return become spaces, as XML says. */
    private String attributeValue() throws Decline {
        expect("=");
        if (at >= s.length() || (s.charAt(at) != '"' && s.charAt(at) != '\'')) {
            throw new Decline();
        }
        char quote = s.charAt(at++);
        StringBuilder v = new StringBuilder();
        while (true) {
            if (at >= s.length()) {
                throw new Decline();
            }
            char c = s.charAt(at);
            if (c == quote) {
                at++;
                return v.toString();
            }
            if (c == '<') {
                throw new Decline();
            }
            if (c == '&') {
                entity(v);
            } else {
                allowed(c);
                v.append(c == '\t' || c == '\n' || c == '\r' ? ' ' : c);
                at++;
            }
        }
    }

    /** Character data up to the next {@code <}; a raw carriage return or {@code ]]>} is declined. */
    private String text() throws Decline {
        StringBuilder v = new StringBuilder();
        while (at < s.length() && s.charAt(at) != '<') {
            char c = s.charAt(at);
            if (c == '&') {
                entity(v);
                continue;
            }
            if (c == '\r' || (c == '>' && at >= 2 && s.startsWith("]]", at - 2))) {
                throw new Decline();
            }
            allowed(c);
            v.append(c);
            at++;
        }
        return v.toString();
    }

    private void entity(StringBuilder v) throws Decline {
        int end = s.indexOf(';', at);
        if (end < 0 || end - at > 10) {
            throw new Decline();
        }
        String e = s.substring(at + 1, end);
        switch (e) {
            case "amp" -> v.append('&');
            case "lt" -> v.append('<');
            case "gt" -> v.append('>');
            case "quot" -> v.append('"');
            case "apos" -> v.append('\'');
            default -> {
                int code;
                try {
                    code = e.startsWith("#x") ? Integer.parseInt(e.substring(2), 16)
                            : e.startsWith("#") ? Integer.parseInt(e.substring(1)) : -1;
                } catch (NumberFormatException bad) {
                    throw new Decline();
                }
                if (code < 0x20 && code != '\t' && code != '\n' && code != '\r' || code > 0xFFFD
                        || code >= 0xD800 && code <= 0xDFFF) {
                    throw new Decline(); // also non-BMP references: rare, left to JAXB
                }
                v.append((char) code);
            }
        }
        at = end + 1;
    }

    /** Characters XML 1.0 forbids (most controls, lone surrogates are kept as pairs by the decoder) are declined. */
    private static void allowed(char c) throws Decline {
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' || c == 0xFFFE || c == 0xFFFF) {
            throw new Decline();
        }
    }

    /** @return whether any space was skipped */
    private boolean space() {
        int from = at;
        while (at < s.length() && (s.charAt(at) == ' ' || s.charAt(at) == '\n' || s.charAt(at) == '\t')) {
            at++;
        }
        return at > from;
    }

    private boolean take(String token) {
        if (s.startsWith(token, at)) {
            at += token.length();
            return true;
        }
        return false;
    }

    private void expect(String token) throws Decline {
        if (!take(token)) {
            throw new Decline();
        }
    }
}
