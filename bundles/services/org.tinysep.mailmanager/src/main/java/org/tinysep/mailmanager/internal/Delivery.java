package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.tinysep.device.support.time.Backoff;

/**
 * One delivery attempt of one message and what follows from it (README, "Retry and give-up policy"): recipients
 * the server accepted are reported delivered; those it refused for good (RFC 5321, {@link SmtpReplies}) are
 * reported failed at once; the others are retried with back-off until the message has failed for
 * {@code giveUpAfterSeconds} (counted on the computer's clock from its first failure), then given up. A failure
 * is remembered ({@link MailSpool#notice}) until a message is delivered to all its recipients.
 */
final class Delivery {

    /**
     * @param retry        the message to try again (with the recipients still to do), or null when it is finished
     * @param delaySeconds when to try it again
     * @param detail       the status detail while retrying
     * @param serverWide   the failure concerned the server, not particular recipients: hold the whole queue
     * @param backoff      the message's back-off after this attempt, to pass to its next one (null when finished)
     */
    record Next(MailMessage retry, long delaySeconds, String detail, boolean serverWide, Backoff backoff) {
        static final Next FINISHED = new Next(null, 0, "", false, null);
    }

    private final SmtpTransport transport;
    private final OutboxEvents events;
    private final Supplier<Instant> clock;
    private final Clock wall;
    private MailSettings settings;
    private MailSpool spool;
    private List<String> warnings = List.of();

    Delivery(SmtpTransport transport, OutboxEvents events, Supplier<Instant> clock, Clock wall) {
        this.transport = transport;
        this.events = events;
        this.clock = clock;
        this.wall = wall;
    }

    /** Takes new settings; warns about how the password is kept. */
    void configure(MailSettings next, MailSpool nextSpool) {
        settings = next;
        spool = nextSpool;
        warnings = List.of();
        warnAboutPassword();
    }

    /** Carries an undelivered-alert notice over to a new spool folder. */
    void moveNotice(MailSpool old) {
        String notice = old.notice();
        try {
            if (notice != null) {
                spool.notice(notice);
                old.notice(null);
            }
        } catch (IOException e) {
            events.problem("cannot move " + old.dir() + "/undelivered.txt to " + spool.dir() + ": " + e);
        }
    }

    Next attempt(MailMessage m, Backoff backoff) {
        List<String> to = m.pending().isEmpty() ? m.recipients(settings.recipients()) : m.pending();
        warnAboutPassword();
        SmtpTransport.Attempt a;
        try {
            a = transport.send(settings, SmtpPassword.read(settings), m, to);
        } catch (IOException e) {
            a = SmtpTransport.Attempt.allTemporary(to, "cannot read the SMTP password file "
                    + settings.passwordFile() + ": " + e.getMessage());
        }
        if (!a.delivered().isEmpty()) {
            events.delivered(m, a.delivered());
            backoff = backoff.reset(); // some got it: the others start again from the first wait
        }
        MailMessage now = m;
        List<String> failures = new ArrayList<>(); // reported once the spool says the same
        if (!a.permanent().isEmpty()) {
            now = now.failing(List.copyOf(a.permanent().keySet()));
            failures.add(MailText.failed(now, a.permanent(), "refused for good by the server, not retried", ""));
        }
        if (a.temporary().isEmpty()) {
            return finish(now, failures);
        }
        Instant wallNow = wall.instant();
        Instant first = m.firstFailure() == null || m.firstFailure().isAfter(wallNow) ? wallNow : m.firstFailure();
        Duration age = Duration.between(first, wallNow);
        if (age.getSeconds() >= settings.giveUpAfterSeconds()) {
            now = now.failing(List.copyOf(a.temporary().keySet()));
            failures.add(MailText.failed(now, a.temporary(), "given up after " + MailText.duration(age) + " of retrying",
                    "last reply: "));
            return finish(now, failures);
        }
        MailMessage retry = now.retrying(List.copyOf(a.temporary().keySet()), List.of(), first);
        try {
            spool.write(retry);
        } catch (IOException e) {
            events.problem("cannot update " + retry + " in the spool " + spool.dir() + ": " + e);
        }
        failures.forEach(w -> fail(m, w));
        long left = settings.giveUpAfterSeconds() - age.getSeconds();
        Backoff failed = backoff.failed();
        long delay = Math.max(1, Math.min(failed.delaySeconds(), left)); // the last try comes at the give-up age
        Instant at = clock.get().plusSeconds(delay);
        events.retrying(m, MailText.retrying(m, a.temporary(), at, delay));
        return new Next(retry, delay, MailText.mail(m) + " not delivered yet to " + MailText.replies(a.temporary())
                + "; attempt " + failed.failures() + " failed, next try at " + MailText.time(at) + " (in " + delay
                + " s)", a.serverWide(), failed);
    }

    /** @param what e.g. {@code mail "Alert" NOT delivered to a@b: refused for good by the server (550 ...)} */
    private void fail(MailMessage m, String what) {
        String notice = what + "; kept in " + spool.dir().resolve("failed");
        events.failed(m, notice);
        try {
            spool.notice(notice);
        } catch (IOException e) {
            events.problem("cannot remember the undelivered alert in " + spool.dir() + ": " + e);
        }
        events.undelivered(notice);
    }

    private Next finish(MailMessage m, List<String> failures) {
        try {
            if (m.failed().isEmpty()) {
                spool.delete(m);
                spool.notice(null);
                events.undelivered(null);
            } else {
                spool.moveToFailed(m);
            }
        } catch (IOException e) {
            events.problem("cannot remove finished " + m + " from the spool (it may be sent again): " + e);
        }
        failures.forEach(w -> fail(m, w));
        return Next.FINISHED;
    }

    /** Reports each warning about the password once, and again only when they change. */
    private void warnAboutPassword() {
        List<String> now = SmtpPassword.warnings(settings);
        if (!now.equals(warnings)) {
            warnings = now;
            now.forEach(events::warning);
        }
    }
}
