package org.tinysep.web.api.internal;

import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;

/**
 * {@code GET /api/stream/events} and {@code /api/stream/packets}: Server-Sent Events, one JSON entry per
 * message with the entry's sequence number as the event id. {@code ?after=<sequence>} or the browser's
 * {@code Last-Event-ID} replays what came after it first. A comment line every {@value #KEEP_ALIVE_S} s keeps the
 * connection open and finds closed ones. A stream ends within {@value #CHECK_MS} ms of its login session ending
 * (logout, a password change, the session's idle time) with an {@code event: ended} message;
 * the slots per log and per login are {@link StreamSlots}'.
 */
final class LiveStreams implements AutoCloseable {

    static final int KEEP_ALIVE_S = 15;
    static final long CHECK_MS = 1000;

    private final LiveFeed<?> events;
    private final LiveFeed<?> packets;
    private final Sessions sessions;
    private final StreamSlots eventSlots = new StreamSlots();
    private final StreamSlots packetSlots = new StreamSlots();
    private volatile boolean closed;

    LiveStreams(LiveFeed<?> events, LiveFeed<?> packets, Sessions sessions) {
        this.events = events;
        this.packets = packets;
        this.sessions = sessions;
    }

    void serve(String which, HttpServletRequest req, HttpServletResponse resp) throws IOException {
        LiveFeed<?> feed = switch (which) {
            case "events" -> events;
            case "packets" -> packets;
            default -> throw ApiException.notFound("no stream '" + which + "': events or packets");
        };
        Sessions.Session session = (Sessions.Session) req.getAttribute(SessionApi.SESSION_ATTRIBUTE);
        if (session == null) {
            throw new ApiException(401, "log in first");
        }
        long after = after(req);
        StreamSlots slots = feed == events ? eventSlots : packetSlots;
        slots.take(session);
        try {
            stream(feed, after, session, resp);
        } finally {
            slots.release(session);
        }
    }

    private void stream(LiveFeed<?> feed, long after, Sessions.Session session, HttpServletResponse resp)
            throws IOException {
        resp.setStatus(200);
        resp.setContentType("text/event-stream;charset=utf-8");
        resp.setHeader("Cache-Control", "no-store");
        resp.setHeader("X-Accel-Buffering", "no");
        OutputStream out = resp.getOutputStream();
        LiveFeed.Subscriber s = feed.subscribe(after);
        try {
            write(out, "retry: 2000\n\n");
            long quietSince = System.nanoTime();
            while (!closed) {
                if (!sessions.alive(session.token())) {
                    write(out, "event: ended\ndata: {\"reason\":\"the login session ended: log in again\"}\n\n");
                    break;
                }
                String m = s.queue.poll(CHECK_MS, TimeUnit.MILLISECONDS);
                if (LiveFeed.END.equals(m)) {
                    break;
                }
                if (m == null) {
                    if (System.nanoTime() - quietSince >= TimeUnit.SECONDS.toNanos(KEEP_ALIVE_S)) {
                        write(out, ": keep-alive\n\n");
                        quietSince = System.nanoTime();
                    }
                    continue;
                }
                quietSince = System.nanoTime();
                StringBuilder batch = new StringBuilder();
                do { // everything waiting goes out with one flush
                    batch.append("id: ").append(idOf(m)).append("\ndata: ").append(m).append("\n\n");
                    m = s.queue.poll();
                } while (m != null && !LiveFeed.END.equals(m));
                write(out, batch.toString());
                if (m != null) {
                    break;
                }
            }
        } catch (IOException e) {
            // the browser went away
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            feed.unsubscribe(s);
        }
    }

    /** The entry's sequence number: the value of the "seq" member every feed message starts with. */
    private static String idOf(String json) {
        int start = json.indexOf(':') + 1;
        int end = json.indexOf(',', start);
        return json.substring(start, end < 0 ? json.length() - 1 : end);
    }

    private static long after(HttpServletRequest req) {
        String v = req.getHeader("Last-Event-ID");
        if (v == null || v.isBlank()) {
            v = req.getParameter("after");
        }
        if (v == null || v.isBlank()) {
            return -1;
        }
        try {
            return Long.parseLong(v.strip());
        } catch (NumberFormatException e) {
            throw ApiException.badRequest("after must be a sequence number, not '" + v + "'");
        }
    }

    private static void write(OutputStream out, String text) throws IOException {
        out.write(text.getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    @Override
    public void close() {
        closed = true;
        events.close();
        packets.close();
    }
}
