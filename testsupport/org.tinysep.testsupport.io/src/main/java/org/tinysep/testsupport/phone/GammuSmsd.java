package org.tinysep.testsupport.phone;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.stream.Stream;

/**
 * The real {@code gammu-smsd} (Debian package gammu-smsd) with Gammu's {@code dummy} phone driver: the "modem" is
 * a folder, so SMS really go through the daemon's files spool (outbox → sent) and an SMS a phone sends is a file in
 * the dummy's inbox folder that the daemon receives into its spool's inbox. {@link #stop()} is the modem unplugged
 * / the daemon not running. The process is ended by its handle, never by name.
 */
public final class GammuSmsd implements AutoCloseable {

    public static final String BINARY = "/usr/bin/gammu-smsd";
    private final Path dir;
    private Process process;
    private int received;

    /** @param dir an empty folder of the test's own: spool/, modem/, gammu-smsdrc, gammu-smsd.pid, smsd.log */
    public GammuSmsd(Path dir) throws IOException {
        this.dir = dir.toAbsolutePath();
        for (String f : List.of("spool/outbox", "spool/inbox", "spool/sent", "spool/error", "modem")) {
            Files.createDirectories(this.dir.resolve(f));
        }
        Files.writeString(config(), String.join("\n", "[gammu]", "device = " + this.dir.resolve("modem"),
                "connection = none", "model = dummy", "", "[smsd]", "service = files",
                "inboxpath = " + spool().resolve("inbox") + "/", "outboxpath = " + spool().resolve("outbox") + "/",
                "sentsmspath = " + spool().resolve("sent") + "/", "errorsmspath = " + spool().resolve("error") + "/",
                "InboxFormat = unicode", "OutboxFormat = unicode", "TransmitFormat = auto",
                "logfile = " + this.dir.resolve("smsd.log"), "debuglevel = 1", "commtimeout = 1", "sendtimeout = 5",
                "receivefrequency = 1", "statusfrequency = 1", "loopsleep = 1", "checksecurity = 0",
                "checkbattery = 0", "checksignal = 0", "resetfrequency = 0", "hardresetfrequency = 0", ""));
    }

    /** @return whether gammu-smsd is installed here */
    public static boolean installed() {
        return Files.isExecutable(Path.of(BINARY));
    }

    public Path spool() {
        return dir.resolve("spool");
    }

    public Path pidFile() {
        return dir.resolve("gammu-smsd.pid");
    }

    public Path config() {
        return dir.resolve("gammu-smsdrc");
    }

    /** Starts the daemon and waits (at most 10 s) until it has written its pid file. */
    public GammuSmsd start() throws IOException, InterruptedException {
        process = new ProcessBuilder(BINARY, "-c", config().toString(), "--pid", pidFile().toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("stdout.log").toFile()).start();
        long end = System.nanoTime() + Duration.ofSeconds(10).toNanos();
        while (!Files.exists(pidFile()) || Files.readString(pidFile()).isBlank()) {
            if (!process.isAlive() || System.nanoTime() > end) {
                throw new IOException("gammu-smsd did not start: " + log());
            }
            Thread.sleep(50);
        }
        return this;
    }

    /** Ends the daemon (modem unplugged); its pid file may stay behind, as after a crash. */
    public void stop() throws InterruptedException {
        if (process != null && process.isAlive()) {
            process.destroy();
            process.waitFor();
        }
    }

    /** A phone sends {@code text} from {@code number}: the dummy modem holds it until gammu-smsd reads it. */
    public void phoneSends(String number, String text) throws IOException {
        Path inbox = dir.resolve("modem/sms/1");
        Files.createDirectories(inbox);
        HexFormat hex = HexFormat.of().withUpperCase();
        String body = String.join("\n", "[SMSBackup000]", "SMSC = \"+4540590000\"",
                "Sent = " + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd'T'HHmmss")),
                "State = UnRead", "PDU = Deliver", "Number = \"" + number + "\"",
                "NumberUnicode = " + hex.formatHex(number.getBytes(StandardCharsets.UTF_16BE)), "Name = \"\"",
                "Text00 = " + hex.formatHex(text.getBytes(StandardCharsets.UTF_16BE)), "Coding = Unicode",
                "Folder = 1", "Length = " + text.length(), "Class = -1", "");
        Path tmp = dir.resolve("phone.tmp");
        Files.writeString(tmp, body);
        Files.move(tmp, inbox.resolve(Integer.toString(++received)));
    }

    /** @return the texts of the SMS gammu-smsd sent (its sent/ folder), each as "number: text", by file name */
    public List<String> sent() throws IOException {
        List<String> all = new ArrayList<>();
        try (Stream<Path> s = Files.list(spool().resolve("sent"))) {
            for (Path p : s.sorted().toList()) {
                String name = p.getFileName().toString();
                String[] parts = name.split("_");
                String number = parts.length >= 4 ? parts[parts.length - 2] : name;
                all.add(number + ": " + text(p));
            }
        }
        return all;
    }

    /** @return the daemon's log, for failure messages */
    public String log() {
        try {
            return Files.readString(dir.resolve("smsd.log")) + Files.readString(dir.resolve("stdout.log"));
        } catch (IOException e) {
            return "(no log: " + e + ")";
        }
    }

    private static String text(Path p) throws IOException {
        byte[] b = Files.readAllBytes(p);
        if (b.length >= 2 && (b[0] & 0xFF) == 0xFF && (b[1] & 0xFF) == 0xFE) {
            return new String(b, 2, b.length - 2, StandardCharsets.UTF_16LE);
        }
        return new String(b, StandardCharsets.UTF_8);
    }

    @Override
    public void close() throws InterruptedException {
        stop();
    }
}
