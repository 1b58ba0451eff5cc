package org.tinysep.mqtt.board.internal;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Consumer;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.tinysep.json.JsonSignature;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The flats the board follows and their keys (docs/central-board.md, "Security"), read once when the board starts:
 * one file {@code <flatKeyDir>/<flatId>.key} per flat, its first line the key of that flat's bridge. A flat without
 * a key file is no flat of this board: its messages are ignored. {@code flats} may narrow the list. Each finding
 * (a listed flat without a key, a key file others may read) is a PROBLEM in the event log.
 */
final class FlatKeys {

    private static final Logger LOG = LoggerFactory.getLogger(FlatKeys.class);
    private static final Pattern FLAT = Pattern.compile("[A-Za-z0-9_.-]{1,64}");

    private final Map<String, byte[]> keys;
    private final Path dir;

    private FlatKeys(Map<String, byte[]> keys, Path dir) {
        this.keys = keys;
        this.dir = dir;
    }

    /**
     * @param flats "*" or empty: every flat with a key file; else the comma-separated flat ids to follow
     */
    static FlatKeys read(Path dir, String flats, Consumer<String> problem) {
        Set<String> wanted = flats == null || flats.isBlank() || flats.strip().equals("*") ? null
                : Arrays.stream(flats.split(",")).map(String::strip).filter(f -> !f.isEmpty())
                        .collect(Collectors.toCollection(TreeSet::new));
        Map<String, byte[]> keys = new HashMap<>();
        if (Files.isDirectory(dir)) {
            try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, "*.key")) {
                for (Path f : files) {
                    String flat = f.getFileName().toString().replaceFirst("\\.key$", "");
                    if (!FLAT.matcher(flat).matches() || wanted != null && !wanted.contains(flat)) {
                        continue;
                    }
                    try {
                        keys.put(flat, JsonSignature.readKey(f, "key"));
                        if (BoardLogin.openToOthers(f)) {
                            say("warning: the key file " + f + " of flat " + flat + " can be read by other users of "
                                    + "this computer; chmod 600 " + f, problem);
                        }
                    } catch (IOException e) {
                        say("Monitoring reduced: the care centre's board ignores flat " + flat + ": " + e.getMessage(),
                                problem);
                    }
                }
            } catch (IOException e) {
                say("Monitoring reduced: the care centre's board cannot read its flats' keys in " + dir + ": "
                        + e.getMessage() + "; it shows no flat", problem);
            }
        }
        if (wanted != null) {
            for (String f : wanted) {
                if (!keys.containsKey(f)) {
                    say("Monitoring reduced: the care centre's board ignores flat " + f + ": it has no key for it ("
                            + dir.resolve(f + ".key") + " is missing or unusable), so it cannot tell its alerts from "
                            + "fakes. Put that flat's key (its bridge's keyFile) there, chmod 600.", problem);
                }
            }
        } else if (keys.isEmpty()) {
            say("Monitoring reduced: the care centre's board follows no flat: there is no flat key in " + dir
                    + " (one file <flatId>.key per flat, the key of that flat's bridge, keyFile).", problem);
        }
        return new FlatKeys(keys, dir);
    }

    private static void say(String words, Consumer<String> problem) {
        LOG.warn("{}", words);
        problem.accept(words);
    }

    /** @return the flat's key, null when the board does not follow that flat */
    byte[] of(String flat) {
        return keys.get(flat);
    }

    int size() {
        return keys.size();
    }

    Path dir() {
        return dir;
    }
}
