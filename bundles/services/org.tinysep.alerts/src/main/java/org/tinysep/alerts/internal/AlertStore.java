package org.tinysep.alerts.internal;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Properties;
import java.util.function.Consumer;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The alerts on disk: one UTF-8 properties file written atomically (temporary file, fsync, rename,
 * {@link AtomicFiles}) after every change, so an alert raised before a power cut or {@code kill -9} is there after
 * the restart. An unreadable alert is skipped and reported; the rest loads.
 */
final class AlertStore {

    /** What the file holds. */
    record Content(List<Alert> alerts, long lastId, LocalDate lastSummary) {
    }

    private final Path file;

    AlertStore(Path file) {
        this.file = file;
    }

    Path file() {
        return file;
    }

    void save(Content c) throws IOException {
        Properties p = new Properties();
        p.setProperty("lastId", Long.toString(c.lastId()));
        if (c.lastSummary() != null) {
            p.setProperty("lastSummary", c.lastSummary().toString());
        }
        p.setProperty("alerts", String.join(",", c.alerts().stream().map(Alert::id).toList()));
        for (Alert a : c.alerts()) {
            String k = "alert." + a.id() + ".";
            p.setProperty(k + "kind", a.kind().name());
            p.setProperty(k + "source", a.source());
            p.setProperty(k + "roomUid", a.roomUid());
            p.setProperty(k + "roomName", a.roomName());
            p.setProperty(k + "raisedAt", a.raisedAt().toString());
            p.setProperty(k + "subject", a.subject());
            p.setProperty(k + "text", a.text());
            p.setProperty(k + "state", a.state().name());
            p.setProperty(k + "contactsReached", Integer.toString(a.contactsReached()));
            p.setProperty(k + "closedAt", a.closedAt() == null ? "" : a.closedAt().toString());
            p.setProperty(k + "closedBy", a.closedBy());
            p.setProperty(k + "notifications", Integer.toString(a.notifications().size()));
            for (int i = 0; i < a.notifications().size(); i++) {
                Notification n = a.notifications().get(i);
                String nk = k + "n" + i + ".";
                p.setProperty(nk + "at", n.at().toString());
                p.setProperty(nk + "step", n.step().name());
                p.setProperty(nk + "to", String.join(",", n.to()));
                p.setProperty(nk + "mailId", n.mailId());
                p.setProperty(nk + "outcome", n.outcome().name());
                p.setProperty(nk + "detail", n.detail());
                p.setProperty(nk + "channel", n.channel());
            }
        }
        StringWriter w = new StringWriter();
        p.store(w, "TinySEP alerts");
        AtomicFiles.createPrivateDirectories(file.getParent());
        AtomicFiles.write(file, w.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** @return what the file holds; nothing when it does not exist */
    Content load(Consumer<String> problems) throws IOException {
        if (!Files.isRegularFile(file)) {
            return new Content(List.of(), 0, null);
        }
        Properties p = new Properties();
        p.load(new StringReader(Files.readString(file, StandardCharsets.UTF_8)));
        long lastId = Long.parseLong(p.getProperty("lastId", "0").strip());
        String summary = p.getProperty("lastSummary");
        List<Alert> alerts = new ArrayList<>();
        for (String id : Arrays.stream(p.getProperty("alerts", "").split(",")).map(String::strip)
                .filter(s -> !s.isEmpty()).toList()) {
            try {
                alerts.add(alert(p, id));
            } catch (RuntimeException e) {
                problems.accept("alert " + id + " in " + file + " could not be read and is skipped: " + e);
            }
        }
        return new Content(alerts, lastId, summary == null || summary.isBlank() ? null : LocalDate.parse(summary));
    }

    private static Alert alert(Properties p, String id) {
        String k = "alert." + id + ".";
        int count = Integer.parseInt(p.getProperty(k + "notifications", "0"));
        List<Notification> ns = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            String nk = k + "n" + i + ".";
            String to = p.getProperty(nk + "to", "");
            ns.add(new Notification(Instant.parse(p.getProperty(nk + "at")),
                    NotificationStep.valueOf(p.getProperty(nk + "step")),
                    to.isBlank() ? List.of() : List.of(to.split(",")), p.getProperty(nk + "mailId"),
                    MailDelivery.Outcome.valueOf(p.getProperty(nk + "outcome")), p.getProperty(nk + "detail"),
                    p.getProperty(nk + "channel", Notification.MAIL)));
        }
        String closedAt = p.getProperty(k + "closedAt", "");
        return new Alert(id, AlertKind.valueOf(p.getProperty(k + "kind")), p.getProperty(k + "source"),
                p.getProperty(k + "roomUid"), p.getProperty(k + "roomName"),
                Instant.parse(p.getProperty(k + "raisedAt")), p.getProperty(k + "subject"),
                p.getProperty(k + "text"), AlertState.valueOf(p.getProperty(k + "state")),
                Integer.parseInt(p.getProperty(k + "contactsReached", "0")),
                closedAt.isBlank() ? null : Instant.parse(closedAt), p.getProperty(k + "closedBy"), ns);
    }
}
