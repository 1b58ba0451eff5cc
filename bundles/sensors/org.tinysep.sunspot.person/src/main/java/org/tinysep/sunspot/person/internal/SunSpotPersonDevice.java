package org.tinysep.sunspot.person.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.ButtonAction;
import org.tinysep.api.sensor.person.ButtonEvent;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.SensorDevice;
import org.tinysep.device.support.sensor.Source;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT person node: its button reports, movement summaries and burst chunks (sensor
 * type 6) become {@link PersonNodeListener} calls; bursts are reassembled first ({@link BurstAssembler}). Listeners
 * hear every report. Button changes, complete bursts and bursts given up are event-log entries in words.
 * <p>
 * A node that also reports as another node type (a room sensor, a pet collar) is not taken as someone's node: its
 * person reports reach no listener, are counted ({@code ignoredReports}) and each button press on it is logged with
 * the reason, so a forged or misprogrammed frame cannot raise a help call through a node the installer placed for
 * something else.
 */
final class SunSpotPersonDevice extends SensorDevice<PersonNodeListener, PersonReport> implements PersonNodeProvider {

    static final String PERSON = "person";
    static final int MAX_NAME = 60;
    private static final Source.Frames FRAMES = new Source.Frames(SunSpotSensorType.PERSON.code(), "person node");

    private final BusRadioSunSpotProvider bus;
    private final BurstAssembler bursts = new BurstAssembler();
    private final Stillness stillness = new Stillness();
    private final AtomicLong burstsReceived = new AtomicLong();
    private final AtomicLong burstsGivenUp = new AtomicLong();
    private final AtomicLong ignored = new AtomicLong();
    private volatile String person = "";
    private volatile MovementSummary lastSummary;
    private volatile ButtonEvent lastButton;

    SunSpotPersonDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Source.sunSpot(bus, FRAMES, SunSpotPayloads::decode, SunSpotPayload.class,
                PersonReport::of), NodeType.PERSON, "Person node " + bus.nodeAddress(), PersonNodeProvider.class);
        this.bus = bus;
    }

    /** @return the node's other types if it is not only a person node, else empty */
    private Set<String> otherTypes() {
        Set<String> others = new TreeSet<>(bus.nodeTypes());
        others.remove(NodeType.PERSON);
        return others;
    }

    @Override
    protected boolean isChange(PersonReport before, PersonReport now) {
        return true; // every report is news: a press, a summary, a chunk
    }

    @Override
    protected boolean tellsEveryReport() {
        return true;
    }

    @Override
    protected void accepted(PersonReport report) {
        if (!otherTypes().isEmpty()) {
            ignored.incrementAndGet();
            return;
        }
        Instant at = at(report);
        for (String words : bursts.expire(at)) {
            gaveUp(words);
        }
        if (report instanceof PersonReport.Summary s) {
            lastSummary = s.summary();
            stillness.add(s.summary());
        } else if (report instanceof PersonReport.Button b) {
            lastButton = b.event();
        } else if (report instanceof PersonReport.Chunk c) {
            BurstAssembler.Outcome outcome = bursts.add(c.chunk(), c.at());
            outcome.givenUp().forEach(this::gaveUp);
            outcome.burst().ifPresent(this::deliver);
        }
    }

    private void gaveUp(String words) {
        burstsGivenUp.incrementAndGet();
        event(words);
    }

    private void deliver(AccelerationBurst burst) {
        burstsReceived.incrementAndGet();
        double peak = burst.samples().stream().mapToDouble(a -> a.magnitudeMg()).max().orElse(0);
        event("acceleration burst received: " + burst.samples().size() + " samples at " + burst.sampleRateHz()
                + " Hz around a peak of " + Math.round(peak) + " mg");
        fire(l -> l.burstReceived(this, burst));
    }

    private static Instant at(PersonReport report) {
        if (report instanceof PersonReport.Summary s) {
            return s.summary().end();
        }
        if (report instanceof PersonReport.Button b) {
            return b.event().at();
        }
        return ((PersonReport.Chunk) report).at();
    }

    @Override
    protected String describe(PersonReport report) {
        if (!(report instanceof PersonReport.Button b)) {
            return null;
        }
        String what = "switch " + b.event().button() + (b.event().action() == ButtonAction.PRESSED ? " pressed"
                : " released");
        Set<String> others = otherTypes();
        if (!others.isEmpty()) {
            return what + " on a node that also reports as " + String.join(", ", others)
                    + ": not taken as a person's switch, nothing is raised (a person node sends only person reports)";
        }
        return what + person().map(p -> " (" + p + ")").orElse("");
    }

    @Override
    protected void tell(PersonNodeListener listener, PersonReport report, boolean first, Instant at) {
        if (!otherTypes().isEmpty()) {
            return;
        }
        if (report instanceof PersonReport.Summary s) {
            listener.movementSummarised(this, s.summary());
        } else if (report instanceof PersonReport.Button b) {
            listener.buttonChanged(this, b.event());
        } // chunks: the assembled burst is fired by accepted()
    }

    @Override
    public Optional<String> person() {
        String p = person;
        return p.isBlank() ? Optional.empty() : Optional.of(p);
    }

    @Override
    public Optional<MovementSummary> lastSummary() {
        return Optional.ofNullable(lastSummary);
    }

    @Override
    protected List<Parameter> settings() {
        return List.of(Parameter.writable(PERSON, person, "who wears this node (a name, e.g. Anna); the help "
                + "button and the event log use it"));
    }

    @Override
    protected Object shownState() {
        MovementSummary s = lastSummary;
        if (s == null) {
            return "";
        }
        Instant still = stillness.since();
        return (still == null ? "moving" : "still since " + still) + " (last summary: peak " + s.peakMg()
                + " mg, spread " + s.magnitudeSdMg() + " mg)";
    }

    @Override
    protected List<Parameter> readings() {
        ButtonEvent b = lastButton;
        return List.of(Parameter.readOnly("state", shownState(), "moving or still since when, and the last summary"),
                Parameter.readOnly("lastUpdate", lastUpdate(), "when the latest report arrived"),
                Parameter.readOnly("stillSince", stillness.since(), "since when the node lies still (spread at most "
                        + Stillness.STILL_SD_MG + " mg, same posture); empty while it moves. A worn node is rarely "
                        + "still for hours"),
                Parameter.readOnly("lastButton", b == null ? "" : "switch " + b.button() + " "
                        + b.action().name().toLowerCase(java.util.Locale.ROOT) + " at " + b.at(), "the last switch change"),
                Parameter.readOnly("burstsReceived", burstsReceived.get(), "acceleration bursts received complete"),
                Parameter.readOnly("burstsGivenUp", burstsGivenUp.get(), "bursts given up incomplete"),
                Parameter.readOnly("ignoredReports", ignored.get(),
                        "person reports ignored because the node also reports as another node type"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!PERSON.equals(key)) {
            throw unknownParameter(key);
        }
        String name = value == null ? "" : value.strip();
        if (name.length() > MAX_NAME || name.chars().anyMatch(Character::isISOControl)) {
            throw new IllegalArgumentException("person must be a name of at most " + MAX_NAME
                    + " characters without control characters, was '" + value + "'");
        }
        person = name;
        event(name.isEmpty() ? "worn by nobody named" : "worn by " + name);
    }
}
