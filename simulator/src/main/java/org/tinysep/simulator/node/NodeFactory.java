package org.tinysep.simulator.node;

import java.io.Closeable;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.simulator.flat.Flat;
import org.tinysep.simulator.flat.Family;
import org.tinysep.simulator.flat.NodeSpec;

/** Creates the nodes of a flat: one UDP socket per AmICA node, one shared socket for the Sun SPOTs. */
public final class NodeFactory {

    private static List<org.tinysep.api.sensor.person.Acceleration> fall;

    private NodeFactory() {
    }

    /** @return the fall a worn person node plays at its wearer's collapse (read once) */
    private static synchronized List<org.tinysep.api.sensor.person.Acceleration> fall() throws IOException {
        if (fall == null) {
            fall = PendantNode.fallRecording();
        }
        return fall;
    }

    /** Nodes that also carry out commands as they arrive (real time); see {@link #create(Flat, Environment, Target, Consumer, boolean)}. */
    public static NodeSet create(Flat flat, Environment env, Target target, Consumer<String> events) throws IOException {
        return create(flat, env, target, events, false);
    }

    /**
     * @param events   receives a line for every command a node carried out
     * @param lockstep carry out commands only at the start of each virtual second, on the simulation's thread
     */
    public static NodeSet create(Flat flat, Environment env, Target target, Consumer<String> events, boolean lockstep)
            throws IOException {
        List<Closeable> resources = new ArrayList<>();
        List<SimNode> nodes = new ArrayList<>();
        List<AmicaNode> amica = new ArrayList<>();
        RoomConditions conditions = new RoomConditions();
        CommandReceiver receiver;
        try {
            SunSpotPort spots = null;
            for (NodeSpec s : flat.nodes()) {
                if (s.family() == Family.AMICA) {
                    AmicaPort port = new AmicaPort(AmicaAddress.parse(s.address()), target);
                    resources.add(port::close);
                    AmicaNode n = new AmicaNode(s, port, env, events);
                    amica.add(n);
                    conditions.add(n);
                    nodes.add(n);
                } else {
                    if (spots == null) {
                        spots = new SunSpotPort(target);
                        resources.add(spots::close);
                    }
                    nodes.add(s.has("person") ? new PendantNode(s, spots, env, fall())
                            : new SunSpotNode(s, spots, env, conditions));
                }
            }
            receiver = new CommandReceiver(amica, !lockstep);
            resources.add(0, receiver::close);
        } catch (IOException | RuntimeException e) {
            new NodeSet(nodes, resources).close();
            throw e;
        }
        return new NodeSet(nodes, resources, receiver::drainNow);
    }
}
