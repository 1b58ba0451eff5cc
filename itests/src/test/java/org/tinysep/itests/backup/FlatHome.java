package org.tinysep.itests.backup;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.itests.TestSyncKey;
import org.tinysep.tools.process.Ports;

/**
 * A distribution home set up for the simulated flat A (like {@code scripts/demo-flat.sh prepare}): free UDP ports
 * on 127.0.0.1 for both bus radios and the time synchroniser (EXTERNAL clock), flat A's house plan and its room
 * placements by node address.
 */
final class FlatHome {

    static final Path FLAT_A = Path.of("..", "simulator", "src", "main", "resources", "flats", "flat-a");

    final Path home;
    final int amicaPort = Ports.freeUdp();
    final int sunSpotPort = Ports.freeUdp();
    final int syncPort = Ports.freeUdp();

    FlatHome(Path home) throws IOException {
        this.home = home;
        Platforms.install(home);
        Path etc = home.resolve("etc");
        Files.writeString(etc.resolve("org.tinysep.amica.busradio.udp.cfg"),
                "port=" + amicaPort + "\nbindAddress=127.0.0.1\n");
        Files.writeString(etc.resolve("org.tinysep.sunspot.busradio.cfg"),
                "udpPort=" + sunSpotPort + "\nudpBindAddress=127.0.0.1\n");
        Files.writeString(etc.resolve("org.tinysep.timecontroller.cfg"),
                "mode=EXTERNAL\nsyncPort=" + syncPort + "\nsyncBindAddress=127.0.0.1\nsyncKeyFile="
                + TestSyncKey.file() + "\nsyncTimeout=0\n");
        Files.writeString(etc.resolve("org.tinysep.houseinformation.placement.cfg"), "placements=" + placements()
                + "\n");
        Files.createDirectories(home.resolve("var"));
        Files.copy(FLAT_A.resolve("house.xml"), home.resolve("var/house.xml"));
    }

    /** @return {@code address=room, ...} for every node of flat A except pet collars */
    static String placements() throws IOException {
        List<String> out = new ArrayList<>();
        for (String line : Files.readAllLines(FLAT_A.resolve("nodes.txt"))) {
            String[] f = line.split("\\|");
            if (line.strip().startsWith("#") || f.length < 5 || (f.length > 5 && f[5].contains("agent="))) {
                continue;
            }
            out.add(f[2].strip() + "=" + f[4].strip());
        }
        return String.join(", ", out);
    }

    /** The simulator's arguments for flat A in lock-step with this home's platform, {@code from}-{@code until}. */
    String[] simulatorArgs(String from, String until) {
        return new String[] {"--lockstep", "--amica-port", Integer.toString(amicaPort), "--sunspot-port",
            Integer.toString(sunSpotPort), "--sync-port", Integer.toString(syncPort), "--sync-key",
            TestSyncKey.file().toString(), "--flat", "flat-a",
            "--scenario", "demo-day", "--seed", "1", "--wander", "0", "--from", from, "--until", until,
            "--progress", "0"};
    }
}
