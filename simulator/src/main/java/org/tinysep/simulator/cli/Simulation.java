package org.tinysep.simulator.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.Set;
import java.util.function.Consumer;
import java.util.stream.Collectors;
import org.tinysep.simulator.agent.Director;
import org.tinysep.simulator.agent.Scenario;
import org.tinysep.simulator.agent.ScenarioParser;
import org.tinysep.simulator.agent.World;
import org.tinysep.simulator.flat.Flat;
import org.tinysep.simulator.flat.NodeSpec;
import org.tinysep.simulator.node.NodeFactory;
import org.tinysep.simulator.node.NodeSet;
import org.tinysep.simulator.node.Target;

/** A flat, its nodes and its agents, played one virtual second at a time by a driver. */
public final class Simulation implements AutoCloseable {

    private final World world = new World();
    private final NodeSet nodes;
    private final Director director;

    /** @param midnight epoch second of the simulated day's 00:00 */
    public Simulation(Flat flat, Scenario scenario, Target target, long midnight, long seed, int jitter, double wander,
            Consumer<String> events) throws IOException {
        this(flat, scenario, target, midnight, seed, jitter, wander, events, false);
    }

    /** @param lockstep nodes carry out commands only at the start of each virtual second (see NodeFactory) */
    public Simulation(Flat flat, Scenario scenario, Target target, long midnight, long seed, int jitter, double wander,
            Consumer<String> events, boolean lockstep) throws IOException {
        this.nodes = NodeFactory.create(flat, world, target, events, lockstep);
        this.director = new Director(flat.house(), flat.entrance().orElse(null), scenario, midnight, seed, jitter,
                wander, world, nodes::power);
    }

    /** Reads a scenario file, or a built-in one ({@code demo-day}) from {@code /scenarios/<name>.txt}. */
    public static Scenario scenario(String fileOrName, Flat flat) throws IOException {
        Path p = Path.of(fileOrName);
        String text;
        if (Files.isRegularFile(p)) {
            text = Files.readString(p);
        } else {
            try (InputStream in = Simulation.class.getResourceAsStream("/scenarios/" + fileOrName + ".txt")) {
                if (in == null) {
                    throw new IOException("no file and no built-in scenario named '" + fileOrName + "' (built in: demo-day)");
                }
                text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            }
        }
        Set<String> ids = flat.nodes().stream().map(NodeSpec::id).collect(Collectors.toSet());
        return new ScenarioParser(flat.house()::roomName, ids).parse(text, fileOrName);
    }

    /** Moves the agents without sending anything (catching up to {@code --from}). */
    public void rehearse(long t) {
        director.advance(t);
    }

    /** Plays second {@code t}: agents move, due nodes send. @return the number of changed reported values */
    public int step(Instant t) {
        director.advance(t.getEpochSecond());
        return nodes.tick(t.getEpochSecond());
    }

    /** @return the instants inside second {@code t} at which a node has a frame due (played after {@link #step}) */
    public java.util.List<Instant> within(Instant t) {
        return nodes.dueWithin(t.getEpochSecond());
    }

    /** Sends what the nodes have due by {@code at}, one of {@link #within}'s instants. @return changed values */
    public int stepWithin(Instant at) {
        return nodes.sendDue(at);
    }

    /** @return this simulation as a driver's stepper: each second, then what falls due inside it */
    public org.tinysep.simulator.time.Stepper stepper() {
        return new org.tinysep.simulator.time.Stepper() {
            @Override
            public int step(Instant t) {
                return Simulation.this.step(t);
            }

            @Override
            public java.util.List<Instant> within(Instant t) {
                return Simulation.this.within(t);
            }

            @Override
            public int stepWithin(Instant at) {
                return Simulation.this.stepWithin(at);
            }
        };
    }

    public World world() {
        return world;
    }

    public NodeSet nodes() {
        return nodes;
    }

    public Director director() {
        return director;
    }

    @Override
    public void close() {
        nodes.close();
    }
}
