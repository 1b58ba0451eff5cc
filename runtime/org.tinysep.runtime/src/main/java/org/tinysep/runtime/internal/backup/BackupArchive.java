package org.tinysep.runtime.internal.backup;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipOutputStream;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamReader;
import org.tinysep.device.support.AtomicFiles;

/**
 * The configuration archive of {@code tinysep:backup} / {@code tinysep:restore} (docs/backup.md): a zip holding
 * {@code backup/<driver>/<file>.xml} (the backup folder without {@code damaged/}), {@code house.xml} and
 * {@code drivers.xml} from the state folder when present, and {@code etc/<name>.cfg}. Reading validates every
 * entry before anything is used: names, sizes, each backup file parses, each XML is well-formed, each cfg loads.
 */
final class BackupArchive {

    static final long MAX_ENTRY_BYTES = 4L << 20;
    static final int MAX_ENTRIES = 10_000;
    private static final Pattern NAME = Pattern.compile(
            "backup/[A-Za-z0-9._-]+/[A-Za-z0-9._-]+\\.xml|house\\.xml|drivers\\.xml|etc/[A-Za-z0-9._-]+\\.cfg");

    private BackupArchive() {
    }

    /** Writes the archive to {@code target} atomically; @return the number of files in it. */
    static int write(Path target, Path backupRoot, Path var, Path etc) throws IOException {
        Map<String, Path> files = new LinkedHashMap<>();
        if (Files.isDirectory(backupRoot)) {
            try (Stream<Path> walk = Files.walk(backupRoot, 2)) {
                walk.filter(Files::isRegularFile).filter(p -> p.getFileName().toString().endsWith(".xml"))
                        .filter(p -> !p.getParent().getFileName().toString().equals(BackupLayout.DAMAGED))
                        .sorted().forEach(p -> files.put("backup/" + backupRoot.relativize(p).toString()
                                .replace('\\', '/'), p));
            }
        }
        for (String name : List.of("house.xml", "drivers.xml")) {
            if (Files.isRegularFile(var.resolve(name))) {
                files.put(name, var.resolve(name));
            }
        }
        if (etc != null && Files.isDirectory(etc)) {
            try (Stream<Path> list = Files.list(etc)) {
                list.filter(p -> p.getFileName().toString().endsWith(".cfg")).sorted()
                        .forEach(p -> files.put("etc/" + p.getFileName(), p));
            }
        }
        Path tmp = Files.createTempFile(target.toAbsolutePath().getParent(), target.getFileName() + ".", ".tmp");
        try {
            try (ZipOutputStream zip = new ZipOutputStream(Files.newOutputStream(tmp))) {
                for (Map.Entry<String, Path> e : files.entrySet()) {
                    zip.putNextEntry(new ZipEntry(e.getKey()));
                    zip.write(Files.readAllBytes(e.getValue()));
                    zip.closeEntry();
                }
            }
            try (var ch = java.nio.channels.FileChannel.open(tmp, java.nio.file.StandardOpenOption.WRITE)) {
                ch.force(true);
            }
            AtomicFiles.move(tmp, target);
        } finally {
            Files.deleteIfExists(tmp);
        }
        return files.size();
    }

    /**
     * Reads and validates the whole archive.
     *
     * @return entry name to content
     * @throws IllegalArgumentException listing every problem found; nothing has been changed
     */
    static Map<String, byte[]> read(Path archive, BackupCodec codec) {
        Map<String, byte[]> out = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        try (ZipFile zip = new ZipFile(archive.toFile())) {
            if (zip.size() > MAX_ENTRIES) {
                throw new IllegalArgumentException(archive + " has more than " + MAX_ENTRIES + " entries");
            }
            Enumeration<? extends ZipEntry> entries = zip.entries();
            while (entries.hasMoreElements()) {
                ZipEntry e = entries.nextElement();
                if (e.isDirectory()) {
                    continue;
                }
                if (!NAME.matcher(e.getName()).matches() || e.getName().contains("..")) {
                    problems.add(e.getName() + ": not a file a TinySEP archive holds");
                    continue;
                }
                byte[] bytes;
                try (InputStream in = zip.getInputStream(e)) {
                    bytes = in.readNBytes((int) MAX_ENTRY_BYTES + 1);
                }
                if (bytes.length > MAX_ENTRY_BYTES) {
                    problems.add(e.getName() + ": larger than " + MAX_ENTRY_BYTES + " bytes");
                    continue;
                }
                String problem = check(e.getName(), bytes, codec);
                if (problem != null) {
                    problems.add(e.getName() + ": " + problem);
                }
                out.put(e.getName(), bytes);
            }
        } catch (IOException e) {
            throw new IllegalArgumentException(archive + " is not a readable zip archive: " + e.getMessage());
        }
        if (out.keySet().stream().noneMatch(n -> n.startsWith("backup/"))) {
            problems.add("no backup/ files: not a TinySEP configuration archive");
        }
        if (!problems.isEmpty()) {
            throw new IllegalArgumentException(archive.getFileName() + " rejected, nothing changed: "
                    + String.join("; ", problems));
        }
        return out;
    }

    private static String check(String name, byte[] bytes, BackupCodec codec) {
        try {
            if (name.startsWith("backup/")) {
                codec.read(bytes);
            } else if (name.endsWith(".xml")) {
                XMLInputFactory f = XMLInputFactory.newFactory();
                f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
                f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
                XMLStreamReader r = f.createXMLStreamReader(new ByteArrayInputStream(bytes));
                while (r.hasNext()) {
                    r.next();
                }
            } else {
                new Properties().load(new StringReader(new String(bytes, java.nio.charset.StandardCharsets.UTF_8)));
            }
            return null;
        } catch (BadBackupException e) {
            return e.getMessage();
        } catch (Exception e) {
            return "malformed: " + String.valueOf(e.getMessage()).replaceAll("\\s+", " ");
        }
    }
}
