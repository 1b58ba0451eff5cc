package org.tinysep.sms.internal;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Stream;

/**
 * gammu-smsd's files spool (man gammu-smsd-files): an SMS to send is a file {@code OUT...txt} in {@code outbox/}
 * (written whole elsewhere and moved in, so gammu-smsd never reads half a file); gammu-smsd moves it to
 * {@code sent/} or {@code error/}. Received SMS appear in {@code inbox/} as {@code IN<date>_<time>_<serial>_<sender>
 * _<part>.txt}; once handled they are moved to {@code handled/}. Texts are written in UTF-16 with a byte-order mark
 * ({@code OutboxFormat = unicode}); received ones are read as UTF-16 when they start with one, else UTF-8.
 */
final class Spool {

    /** Where a message handed over stands. */
    enum Where { OUTBOX, SENT, ERROR, GONE }

    /** A received SMS: its file, the sender's number and its text. */
    record Incoming(Path file, String from, String text) {
    }

    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd_HHmmss")
            .withZone(ZoneOffset.UTC);
    private final Path base;
    private final AtomicLong serial = new AtomicLong();

    Spool(Path base) {
        this.base = base;
    }

    Path base() {
        return base;
    }

    Path folder(String name) {
        return base.resolve(name);
    }

    /** @return the folders gammu-smsd needs that are missing, in words; empty when all are there */
    List<String> missing() {
        return Stream.of("outbox", "inbox", "sent", "error").filter(f -> !Files.isDirectory(folder(f)))
                .map(f -> folder(f).toString()).toList();
    }

    /** @return the id of the message (its file name) */
    String queue(String number, String text, Instant now) throws IOException {
        long n = serial.incrementAndGet();
        String name = "OUTA" + STAMP.format(now) + "_" + String.format("%02d", n % 100) + "_" + number + "_tinysep"
                + Long.toString(now.toEpochMilli(), 36) + n + ".txt";
        Path tmp = base.resolve(".writing-" + name);
        ByteBuffer body = StandardCharsets.UTF_16LE.encode(text);
        byte[] bytes = new byte[2 + body.remaining()];
        bytes[0] = (byte) 0xFF;
        bytes[1] = (byte) 0xFE;
        body.get(bytes, 2, bytes.length - 2);
        Files.write(tmp, bytes);
        Files.move(tmp, folder("outbox").resolve(name), StandardCopyOption.ATOMIC_MOVE);
        return name;
    }

    Where where(String id) {
        if (id.contains("/") || id.contains("\\")) {
            return Where.GONE;
        }
        for (Where w : List.of(Where.SENT, Where.ERROR, Where.OUTBOX)) {
            if (Files.exists(folder(w.name().toLowerCase()).resolve(id))) {
                return w;
            }
        }
        return Where.GONE;
    }

    /** @return whether any SMS waits in the outbox (false when it cannot be read) */
    boolean outboxWaiting() {
        try (Stream<Path> s = Files.list(folder("outbox"))) {
            return s.anyMatch(Spool::outgoing);
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /** @return how many SMS have waited in the outbox for longer than {@code limit} */
    int waitingLongerThan(Duration limit, Instant now) {
        try (Stream<Path> s = Files.list(folder("outbox"))) {
            return (int) s.filter(Spool::outgoing).filter(p -> {
                try {
                    return Files.getLastModifiedTime(p).toInstant().plus(limit).isBefore(now);
                } catch (IOException e) {
                    return false;
                }
            }).count();
        } catch (IOException e) {
            return 0;
        }
    }

    /** @return whether {@code p} is an SMS gammu-smsd is to send (its outbox files are named OUT…) */
    private static boolean outgoing(Path p) {
        return p.getFileName().toString().startsWith("OUT");
    }

    /** @return the received SMS not handled yet, oldest name first */
    List<Incoming> incoming() throws IOException {
        List<Incoming> all = new ArrayList<>();
        try (Stream<Path> s = Files.list(folder("inbox"))) {
            for (Path p : s.filter(p -> p.getFileName().toString().matches("IN.*\\.txt")).sorted().toList()) {
                all.add(new Incoming(p, sender(p.getFileName().toString()), read(p)));
            }
        }
        return all;
    }

    void handled(Incoming in) throws IOException {
        Path to = folder("handled");
        Files.createDirectories(to);
        Files.move(in.file(), to.resolve(in.file().getFileName()), StandardCopyOption.ATOMIC_MOVE,
                StandardCopyOption.REPLACE_EXISTING);
    }

    /** @return the sender of {@code IN20021130_021531_00_+45409000931640979_00.txt} */
    static String sender(String name) {
        String[] p = name.substring(2, name.length() - 4).split("_");
        return p.length < 5 ? "" : String.join("_", java.util.Arrays.copyOfRange(p, 3, p.length - 1));
    }

    static String read(Path p) throws IOException {
        byte[] b = Files.readAllBytes(p);
        if (b.length >= 2 && (b[0] & 0xFF) == 0xFF && (b[1] & 0xFF) == 0xFE) {
            return new String(b, 2, b.length - 2, StandardCharsets.UTF_16LE);
        }
        if (b.length >= 2 && (b[0] & 0xFF) == 0xFE && (b[1] & 0xFF) == 0xFF) {
            return new String(b, 2, b.length - 2, StandardCharsets.UTF_16BE);
        }
        return new String(b, StandardCharsets.UTF_8);
    }
}
