package org.tinysep.launcher;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;

/** A file of {@code etc/} as the launcher reads it before the framework starts (FileInstall reads it again later). */
final class CfgFile {

    private CfgFile() {
    }

    /**
     * @return the file's keys and values as {@link Properties#load} reads them (ISO-8859-1), empty when it is missing
     * @throws IOException              when it cannot be read
     * @throws IllegalArgumentException when a value has a malformed escape
     */
    static Properties load(Path cfg) throws IOException {
        Properties p = new Properties();
        if (Files.isRegularFile(cfg)) {
            try (Reader r = Files.newBufferedReader(cfg, StandardCharsets.ISO_8859_1)) {
                p.load(r);
            }
        }
        return p;
    }
}
