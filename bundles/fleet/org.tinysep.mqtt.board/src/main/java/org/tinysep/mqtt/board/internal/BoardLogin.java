package org.tinysep.mqtt.board.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The board's broker login, settled when the board starts (docs/central-board.md, "Security"): a user name and the
 * password from {@code passwordFile}. Without a user name the broker would have to let anyone in: refused unless
 * {@code allowAnonymous=true} (then a loud warning). Every finding is a PROBLEM in the event log.
 *
 * @param username empty = anonymous
 * @param password the password, empty when anonymous
 * @param refusal  why the board does not connect, else null
 */
record BoardLogin(String username, char[] password, String refusal) {

    private static final Logger LOG = LoggerFactory.getLogger(BoardLogin.class);

    static BoardLogin of(BoardConfig c, Path var, Consumer<String> problem) {
        String url = BoardClient.shown(c.brokerUrl());
        String user = c.username().strip();
        if (user.isEmpty()) {
            if (!c.allowAnonymous()) {
                return refuse("Monitoring reduced: the care centre's board does not connect to " + url + ", so it "
                        + "shows no flat's alerts: no broker login is configured (username and passwordFile in "
                        + "configuration org.tinysep.mqtt.board). A broker that lets clients in without a login lets "
                        + "anyone acknowledge the flats' alerts and put fake flats and alerts on the board. Set a "
                        + "login (or allowAnonymous=true, not recommended).", problem);
            }
            warn("The care centre's board connects to " + url + " WITHOUT a login (allowAnonymous=true): anyone who "
                    + "can reach this broker can publish to the flats' topics; the board still shows only signed "
                    + "messages of the flats it has keys for. Set username and passwordFile to end this.", problem);
            return new BoardLogin("", new char[0], null);
        }
        if (!c.password().isEmpty()) {
            warn("The care centre's board reads its broker password from its configuration (key password), kept in "
                    + "ConfigAdmin's files: put it into a file (chmod 600), set passwordFile and remove password.",
                    problem);
            return new BoardLogin(user, c.password().toCharArray(), null);
        }
        Path file = c.passwordFile().isBlank() ? var.resolve("secrets").resolve("mqtt-board.password")
                : Path.of(c.passwordFile().strip());
        try {
            String all = Files.readString(file, StandardCharsets.UTF_8);
            String line = all.lines().findFirst().orElse("");
            if (line.isEmpty()) {
                throw new IOException("the file is empty");
            }
            if (openToOthers(file)) {
                warn("warning: the care centre board's password file " + file + " can be read by other users of this "
                        + "computer; chmod 600 " + file, problem);
            }
            return new BoardLogin(user, line.toCharArray(), null);
        } catch (IOException e) {
            return refuse("Monitoring reduced: the care centre's board does not connect to " + url + ", so it shows "
                    + "no flat's alerts: its password file " + file + " cannot be read (" + e.getMessage() + "). Put "
                    + "the broker password of user " + user + " into it (chmod 600), or set passwordFile.", problem);
        }
    }

    static boolean openToOthers(Path file) {
        try {
            return Files.getPosixFilePermissions(file).stream().anyMatch(p -> !p.name().startsWith("OWNER_"));
        } catch (IOException | UnsupportedOperationException e) {
            return false;
        }
    }

    private static BoardLogin refuse(String why, Consumer<String> problem) {
        LOG.warn("{}", why);
        problem.accept(why);
        return new BoardLogin("", new char[0], why);
    }

    private static void warn(String words, Consumer<String> problem) {
        LOG.warn("{}", words);
        problem.accept(words);
    }
}
