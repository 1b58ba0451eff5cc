package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.tools.process.PlatformProcess;

/**
 * The flat of the kill-and-restart process tests, written into a fresh copy of the distribution before it starts: a
 * hall and a bathroom ({@code var/house.xml}), AmICA movement node 1.40 placed in the bathroom, an inactivity limit
 * of 1 min there (UTC), real time and the UDP bus radio on a free port; and the person moving in that bathroom.
 * Written once for KillRestartIT and AlertKillRestartIT, which add their own configuration on top.
 *
 * @param home the distribution copy
 * @param radioPort the UDP bus radio's port on 127.0.0.1
 */
record BathroomFlat(Path home, int radioPort) {

    /** Copies the distribution to {@code home} and sets the flat up there. */
    static BathroomFlat create(Path home) throws IOException {
        int port = new TestDistribution(home, null).realTimeAmicaRadio();
        Files.writeString(home.resolve("etc/org.tinysep.inactivity.cfg"), "roomLimits=Bathroom=1\ntimeZone=UTC\n");
        Files.writeString(home.resolve("etc/org.tinysep.houseinformation.placement.cfg"), "placements=1.40=Bathroom\n");
        Files.createDirectories(home.resolve("var"));
        Files.writeString(home.resolve("var/house.xml"), """
                <?xml version="1.0" encoding="UTF-8"?>
                <HOUSE_ROOMS>
                    <ROOM><UID>b1000000-0000-4000-8000-000000000001</UID><NAME>Hall</NAME><TYPE>Hall</TYPE>
                        <NEIGHBORS><ROOM_UID>b1000000-0000-4000-8000-000000000002</ROOM_UID></NEIGHBORS></ROOM>
                    <ROOM><UID>b1000000-0000-4000-8000-000000000002</UID><NAME>Bathroom</NAME><TYPE>Bathroom</TYPE>
                        <NEIGHBORS><ROOM_UID>b1000000-0000-4000-8000-000000000001</ROOM_UID></NEIGHBORS></ROOM>
                </HOUSE_ROOMS>
                """);
        return new BathroomFlat(home, port);
    }

    /** @return a sender of AmICA frames to this flat's bus radio */
    AmicaSender sender() throws IOException {
        return new AmicaSender(radioPort);
    }

    /** @return the movement node placed in the bathroom (1.40), sending through {@code sender} */
    static AmicaSender.Node bathroomNode(AmicaSender sender) {
        return sender.node(1, 40);
    }

    /**
     * Sends motion from {@code bath} every 0.5 s until Inactivity Recognition watches the bathroom with a movement
     * there later than {@code after} (placement is applied in the background); fails after {@code wait}.
     *
     * @return the time of that movement, as Inactivity Recognition shows it
     */
    static Instant moveInBathroom(PlatformProcess p, AmicaSender.Node bath, Instant after, Duration wait)
            throws Exception {
        long end = System.nanoTime() + wait.toNanos();
        while (System.nanoTime() < end) {
            bath.motion(true);
            Thread.sleep(500);
            String line = inactivity(p);
            Matcher m = Pattern.compile("lastActivity=movement by [^,]* in Bathroom at (\\S+Z)").matcher(line);
            if (m.find() && line.contains("state=WATCHING")) {
                Instant at = Instant.parse(m.group(1));
                if (after == null || at.isAfter(after)) {
                    return at;
                }
            }
        }
        throw new AssertionError("no bathroom activity seen: " + inactivity(p));
    }

    /** @return the parameters line of the Inactivity Recognition device in {@code tinysep:devices} ("" before it) */
    static String inactivity(PlatformProcess p) {
        return p.text("tinysep:devices").lines().dropWhile(l -> !l.contains(" InactivityRecognition "))
                .filter(l -> l.strip().startsWith("parameters:")).findFirst().orElse("");
    }
}
