package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Stream;

/**
 * What a restore changes in {@code etc/*.cfg}: every setting whose value differs before and
 * after, as {@code <file> <key>: <old> → <new>}; values of passwords and keys are not shown.
 */
final class SettingChanges {

    private SettingChanges() {
    }

    /** @return every setting of {@code etc/*.cfg} as "file key" → value (empty when there is no etc folder) */
    static TreeMap<String, String> read(Path etc) {
        TreeMap<String, String> out = new TreeMap<>();
        if (etc == null || !Files.isDirectory(etc)) {
            return out;
        }
        try (Stream<Path> list = Files.list(etc)) {
            for (Path cfg : list.filter(p -> p.getFileName().toString().endsWith(".cfg")).sorted().toList()) {
                Properties p = new Properties();
                try (Reader r = Files.newBufferedReader(cfg, StandardCharsets.ISO_8859_1)) {
                    p.load(r);
                } catch (IOException | IllegalArgumentException e) {
                    continue; // an unreadable file: its settings are not compared
                }
                p.stringPropertyNames().forEach(k -> out.put(cfg.getFileName() + " " + k, p.getProperty(k).strip()));
            }
        } catch (IOException e) {
            return out;
        }
        return out;
    }

    /** @return one line per changed, added or removed setting, in file and key order */
    static List<String> diff(TreeMap<String, String> before, TreeMap<String, String> after) {
        List<String> out = new ArrayList<>();
        TreeSet<String> keys = new TreeSet<>(before.keySet());
        keys.addAll(after.keySet());
        for (String k : keys) {
            String was = before.get(k);
            String now = after.get(k);
            if (was == null ? now != null : !was.equals(now)) {
                boolean secret = k.toLowerCase().matches(".*(password|secret|key).*");
                out.add(k + ": " + (secret ? "(a secret, changed)" : show(was) + " → " + show(now)));
            }
        }
        return out;
    }

    private static String show(String v) {
        return v == null ? "(not set)" : v.isEmpty() ? "(empty)" : v;
    }
}
