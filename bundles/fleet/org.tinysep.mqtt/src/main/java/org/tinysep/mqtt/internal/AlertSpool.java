package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The alert messages on disk, so none is lost while the broker is down or the platform restarts:
 * {@code outbox/<seq>.msg} waits for the broker's acknowledgement (PUBACK), {@code delivered/<alertId>.msg} keeps
 * the last delivered message of each alert (re-published with its original {@code seq} after every reconnection,
 * in case the broker lost its retained messages), {@code seq} the last number given. Every write is atomic
 * ({@link AtomicFiles}). Used only on the bridge's own thread.
 */
final class AlertSpool {

    private static final Logger LOG = LoggerFactory.getLogger(AlertSpool.class);

    private final Path outbox;
    private final Path delivered;
    private final Path seqFile;
    private final TreeMap<Long, Message> pending = new TreeMap<>();
    private final Map<String, Message> done = new TreeMap<>();
    private long seq;

    AlertSpool(Path dir) throws IOException {
        this.outbox = AtomicFiles.createPrivateDirectories(dir.resolve("outbox"));
        this.delivered = AtomicFiles.createPrivateDirectories(dir.resolve("delivered"));
        this.seqFile = dir.resolve("seq");
        if (Files.exists(seqFile)) {
            try {
                seq = Long.parseLong(Files.readString(seqFile, StandardCharsets.UTF_8).strip());
            } catch (NumberFormatException e) {
                LOG.warn("MQTT outbox: {} is unreadable, seq numbers go on from the messages on disk", seqFile);
            }
        }
        for (Message m : read(outbox)) {
            pending.put(m.key(), m);
            seq = Math.max(seq, m.key());
        }
        for (Message m : read(delivered)) {
            done.put(m.alertId(), m);
            seq = Math.max(seq, m.key());
        }
    }

    /** @return the next per-flat seq, saved before it is used */
    long nextSeq() throws IOException {
        long next = seq + 1;
        AtomicFiles.write(seqFile, Long.toString(next).getBytes(StandardCharsets.UTF_8));
        seq = next;
        return next;
    }

    /** Keeps the message on disk until {@link #delivered} (its key is its seq). */
    void add(Message m) throws IOException {
        AtomicFiles.write(outbox.resolve(name(m.key())), encode(m));
        pending.put(m.key(), m);
    }

    /** The broker acknowledged it: remembered as the alert's last delivered message (an empty one forgets it). */
    void delivered(Message m) throws IOException {
        if (!pending.containsKey(m.key())) {
            return;
        }
        Path last = delivered.resolve(Topics.level(m.alertId()) + ".msg");
        if (m.payload().length == 0) {
            Files.deleteIfExists(last);
            done.remove(m.alertId());
        } else {
            AtomicFiles.write(last, encode(m));
            done.put(m.alertId(), m);
        }
        AtomicFiles.delete(outbox.resolve(name(m.key())));
        pending.remove(m.key());
    }

    /** @return the messages waiting for the broker, oldest seq first */
    List<Message> pending() {
        return new ArrayList<>(pending.values());
    }

    /** @return the last delivered message of each alert not yet emptied */
    List<Message> delivered() {
        return new ArrayList<>(done.values());
    }

    /** @return the newest message about the alert, waiting or delivered, or null */
    Message latest(String alertId) {
        Message newest = done.get(alertId);
        for (Message m : pending.values()) {
            if (m.alertId().equals(alertId) && (newest == null || m.key() > newest.key())) {
                newest = m;
            }
        }
        return newest;
    }

    /** @return the ids of every alert with a retained message on disk */
    List<String> alertIds() {
        List<String> ids = new ArrayList<>(done.keySet());
        pending.values().stream().map(Message::alertId).filter(id -> !ids.contains(id)).forEach(ids::add);
        return ids;
    }

    int size() {
        return pending.size();
    }

    private static String name(long key) {
        return String.format("%020d.msg", key);
    }

    private static byte[] encode(Message m) {
        byte[] head = (m.topic() + "\n" + (m.retained() ? "1" : "0") + "\n" + m.key() + "\n" + m.alertId() + "\n")
                .getBytes(StandardCharsets.UTF_8);
        byte[] all = Arrays.copyOf(head, head.length + m.payload().length);
        System.arraycopy(m.payload(), 0, all, head.length, m.payload().length);
        return all;
    }

    private static Message decode(byte[] b) {
        int[] nl = new int[4];
        int found = 0;
        for (int i = 0; i < b.length && found < 4; i++) {
            if (b[i] == '\n') {
                nl[found++] = i;
            }
        }
        if (found < 4) {
            throw new IllegalArgumentException("cut short");
        }
        String topic = new String(b, 0, nl[0], StandardCharsets.UTF_8);
        boolean retained = b[nl[0] + 1] == '1';
        long key = Long.parseLong(new String(b, nl[1] + 1, nl[2] - nl[1] - 1, StandardCharsets.UTF_8));
        String alertId = new String(b, nl[2] + 1, nl[3] - nl[2] - 1, StandardCharsets.UTF_8);
        return new Message(topic, Arrays.copyOfRange(b, nl[3] + 1, b.length), retained, key, alertId);
    }

    private static List<Message> read(Path dir) throws IOException {
        List<Message> out = new ArrayList<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, "*.msg")) {
            for (Path f : files) {
                try {
                    out.add(decode(Files.readAllBytes(f)));
                } catch (RuntimeException e) {
                    Path aside = AtomicFiles.moveAside(f, Instant.now());
                    LOG.warn("MQTT outbox: {} is damaged ({}), moved aside to {}", f, e.getMessage(), aside);
                }
            }
        }
        return out;
    }
}
