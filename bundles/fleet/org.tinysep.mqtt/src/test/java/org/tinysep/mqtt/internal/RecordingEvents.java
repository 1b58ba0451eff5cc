package org.tinysep.mqtt.internal;

import java.nio.charset.StandardCharsets;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** The link's events as lines, in order, for tests: {@code connected}, {@code failed: why} … */
final class RecordingEvents implements Link.Events {

    private final LinkedBlockingQueue<String> events = new LinkedBlockingQueue<>();

    /** @return the next event, waiting at most 60 s */
    String next() throws InterruptedException {
        String e = events.poll(60, TimeUnit.SECONDS);
        return e == null ? "(nothing within 60 s)" : e;
    }

    @Override
    public void connected(int generation) {
        events.add("connected");
    }

    @Override
    public void failed(int generation, String why, boolean refused) {
        events.add("failed" + (refused ? " (refused)" : "") + ": " + why);
    }

    @Override
    public void lost(int generation, String why) {
        events.add("lost: " + why);
    }

    @Override
    public void published(int generation, Message m, boolean ok) {
        events.add("published " + m.topic() + " " + ok);
    }

    @Override
    public void command(String topic, byte[] payload) {
        events.add("command " + topic + " " + new String(payload, StandardCharsets.UTF_8));
    }
}
