package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import java.util.function.Predicate;

/**
 * The configuration files ({@code etc/*.cfg}) that TinySEP owns, and the keys an archive never carries or changes
 * (docs/backup.md § What a restore may change). Only these files go into an archive and only these come out of one:
 * FileInstall's own configuration ({@code org.apache.felix.fileinstall*}) or any other PID could make the platform
 * install and run code from anywhere.
 */
final class OwnedConfig {

    /** Singleton PIDs of the shipped bundles: {@code <pid>.cfg}. */
    static final Set<String> PIDS = Set.of("org.tinysep.runtime", "org.tinysep.runtime.backup", "org.tinysep.drivers",
            "org.tinysep.amica.busradio.udp", "org.tinysep.sunspot.busradio", "org.tinysep.timecontroller",
            "org.tinysep.houseinformation", "org.tinysep.houseinformation.placement", "org.tinysep.flatoccupancy",
            "org.tinysep.inactivity", "org.tinysep.followmelight", "org.tinysep.mailmanager");
    /** Factory PIDs of the shipped bundles: {@code <factoryPid>-<name>.cfg}. */
    static final Set<String> FACTORY_PIDS = Set.of("org.tinysep.amica.busradio.serial");
    static final String TIME_CONTROLLER = "org.tinysep.timecontroller.cfg";

    private OwnedConfig() {
    }

    /** @return whether {@code fileName} ({@code x.cfg}) configures a PID TinySEP owns */
    static boolean owned(String fileName) {
        if (!fileName.endsWith(".cfg")) {
            return false;
        }
        String pid = fileName.substring(0, fileName.length() - 4);
        return PIDS.contains(pid) || FACTORY_PIDS.stream().anyMatch(f -> pid.startsWith(f + "-")
                && pid.length() > f.length() + 1);
    }

    /** A key no backup holds: any whose name contains {@code password} or {@code secret} (any case). */
    static boolean secret(String key) {
        String k = key.toLowerCase(java.util.Locale.ROOT);
        return k.contains("password") || k.contains("secret");
    }

    /**
     * Keys a restore never changes: the Time Controller's {@code mode} (a restore must not switch the clock
     * silently), secrets, and every key naming a file or folder (where things live belongs to this installation;
     * an archive pointing e.g. the drivers list elsewhere could install any bundle).
     */
    static boolean keptOnRestore(String fileName, String key) {
        return secret(key) || (fileName.equals(TIME_CONTROLLER) && key.equals("mode")) || key.equals("file")
                || key.equals("folder") || key.endsWith("File") || key.endsWith("Folder") || key.endsWith("Path")
                || key.endsWith("Dir") || key.endsWith("Directory");
    }

    /** @return {@code cfg} without its secret keys (what {@code tinysep:backup} puts into an archive) */
    static byte[] forBackup(byte[] cfg) {
        return join(without(lines(cfg), OwnedConfig::secret));
    }

    /** The restored content of one cfg file and what was kept from the installation's own file. */
    record Merged(byte[] content, List<String> notes) {
    }

    /**
     * @param archived the file in the archive
     * @param current  the file here now, or null
     * @return the archive's file with this installation's kept keys ({@link #keptOnRestore}) instead of its own
     */
    static Merged forRestore(String fileName, byte[] archived, byte[] current) {
        List<String[]> mine = current == null ? List.of() : lines(current);
        List<String[]> theirs = lines(archived);
        List<String> notes = new ArrayList<>();
        Properties a = properties(theirs);
        Properties c = properties(mine);
        for (String key : a.stringPropertyNames()) {
            if (keptOnRestore(fileName, key) && !a.getProperty(key).equals(c.getProperty(key))) {
                notes.add(fileName + ": kept this installation's " + key + (secret(key) ? ""
                        : " (" + (c.getProperty(key) == null ? "not set" : c.getProperty(key)) + ")")
                        + "; the archive's " + (secret(key) ? "value" : a.getProperty(key)) + " was not applied"
                        + (key.equals("mode") ? " (change the clock with tinysep:time)" : ""));
            }
        }
        List<String[]> kept = new ArrayList<>(mine.stream().filter(l -> l[0] != null
                && keptOnRestore(fileName, l[0])).toList());
        List<String[]> out = new ArrayList<>();
        for (String[] line : theirs) {
            if (line[0] == null || !keptOnRestore(fileName, line[0])) {
                out.add(line);
            } else { // this installation's line in its place, so the file reads as before
                kept.stream().filter(k -> k[0].equals(line[0])).findFirst().ifPresent(k -> {
                    out.add(k);
                    kept.remove(k);
                });
            }
        }
        out.addAll(kept);
        return new Merged(join(out), notes);
    }

    /** @return the logical lines of a properties file: {key or null (comment, blank), raw text with newlines} */
    private static List<String[]> lines(byte[] cfg) {
        List<String[]> out = new ArrayList<>();
        String[] raw = new String(cfg, StandardCharsets.UTF_8).split("\n", -1);
        StringBuilder logical = new StringBuilder();
        for (int i = 0; i < raw.length; i++) {
            if (i == raw.length - 1 && raw[i].isEmpty()) {
                break;
            }
            logical.append(raw[i]).append('\n');
            String line = raw[i].replace("\r", "");
            boolean comment = logical.length() == raw[i].length() + 1
                    && (line.strip().startsWith("#") || line.strip().startsWith("!"));
            if (!comment && continues(line)) {
                continue;
            }
            Properties p = properties(logical.toString());
            String key = p.isEmpty() ? null : p.stringPropertyNames().iterator().next();
            out.add(new String[] {key, logical.toString()});
            logical.setLength(0);
        }
        if (logical.length() > 0) {
            Properties p = properties(logical.toString());
            out.add(new String[] {p.isEmpty() ? null : p.stringPropertyNames().iterator().next(), logical.toString()});
        }
        return out;
    }

    private static boolean continues(String line) {
        int n = 0;
        for (int i = line.length() - 1; i >= 0 && line.charAt(i) == '\\'; i--) {
            n++;
        }
        return n % 2 == 1;
    }

    private static List<String[]> without(List<String[]> lines, Predicate<String> drop) {
        return lines.stream().filter(l -> l[0] == null || !drop.test(l[0])).toList();
    }

    private static byte[] join(List<String[]> lines) {
        StringBuilder b = new StringBuilder();
        lines.forEach(l -> b.append(l[1].endsWith("\n") ? l[1] : l[1] + "\n"));
        return b.toString().getBytes(StandardCharsets.UTF_8);
    }

    private static Properties properties(List<String[]> lines) {
        return properties(new String(join(lines), StandardCharsets.UTF_8));
    }

    private static Properties properties(String text) {
        Properties p = new Properties();
        try {
            p.load(new StringReader(text));
        } catch (IOException | IllegalArgumentException e) {
            // malformed: validation reports it; here it holds no key
        }
        return p;
    }
}
