package org.tinysep.runtime.internal.health;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Optional;
import java.util.Properties;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.device.support.files.AtomicFiles;
import org.tinysep.device.support.files.StateFolder;

/**
 * Tells that the platform was restarted after a failure (the platform cannot die silently). The launcher (or
 * its supervisor) leaves {@value #FILE} in the state folder when the last run ended without a clean stop: a hang, an
 * error exit, a crash, a power cut. On activation its sentence ("TinySEP was restarted at 10:02 after it stopped
 * responding at 09:58 (Europe/Berlin)") goes to the event log as a {@code PROBLEM}, once; as soon as a Mail Manager
 * is there it is mailed to the caregivers, and the note is deleted. A note not yet mailed survives a further restart.
 */
@Component(immediate = true, service = {})
public final class RestartReporter {

    /** The note's file name in the state folder (written by the launcher's {@code RestartNote}). */
    public static final String FILE = "restart-note.properties";
    static final String ORIGIN = "platform";
    static final String SUBJECT = "TinySEP was restarted after a failure";
    private static final Logger LOG = LoggerFactory.getLogger(RestartReporter.class);

    @Reference
    EventLog eventLog; // package-private: tests set it
    private Path note;
    private String message;

    @Activate
    void activate(BundleContext context) {
        activate(StateFolder.resolve(null, context, FILE).orElse(null));
    }

    /** Activation body and test seam: {@code file} is the note (null: no state folder, nothing to do). */
    synchronized void activate(Path file) {
        note = file;
        Optional<Properties> p = file == null ? Optional.empty() : read(file);
        message = p.map(n -> n.getProperty("message")).filter(m -> !m.isBlank()).orElse(null);
        if (message == null) {
            return;
        }
        if (!"true".equals(p.get().getProperty("logged"))) {
            eventLog.record(EventKind.PROBLEM, ORIGIN, message);
            LOG.warn("{}", message);
            p.get().setProperty("logged", "true");
            save(p.get());
        }
        mailIfPossible();
    }

    private MailManagerProvider mail;

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    synchronized void bindMail(MailManagerProvider provider) {
        mail = provider;
        mailIfPossible();
    }

    synchronized void unbindMail(MailManagerProvider provider) {
        if (mail == provider) {
            mail = null;
        }
    }

    private void mailIfPossible() {
        if (message == null || mail == null || note == null) {
            return;
        }
        mail.send(SUBJECT, message + ".\n\nWhile TinySEP was not running nobody was watched over: an alert that fell "
                + "due meanwhile was raised after the restart. The event log (tinysep:events --kind PROBLEM) "
                + "has the details.");
        eventLog.record(EventKind.DEVICE_EVENT, ORIGIN, "the restart was handed to the Mail Manager for the "
                + "caregivers");
        try {
            AtomicFiles.delete(note);
        } catch (IOException e) {
            LOG.warn("Cannot delete {}: {}", note, e.toString());
        }
        message = null;
    }

    private static Optional<Properties> read(Path file) {
        try {
            Properties p = new Properties();
            p.load(new StringReader(Files.readString(file, StandardCharsets.UTF_8)));
            return Optional.of(p);
        } catch (NoSuchFileException e) {
            return Optional.empty();
        } catch (IOException | IllegalArgumentException e) {
            LOG.warn("Cannot read {}: {}", file, e.toString());
            return Optional.empty();
        }
    }

    private void save(Properties p) {
        try {
            StringWriter text = new StringWriter();
            p.store(text, null);
            AtomicFiles.write(note, text.toString().getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            LOG.warn("Cannot update {}: {}", note, e.toString());
        }
    }
}
