package org.tinysep.simulator.node;

import java.net.InetAddress;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.simulator.flat.FlatLoader;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/** Flat A's nodes sending to two stand-in radios, with a scripted environment. */
abstract class NodeTestSupport {

    static final long T0 = 1_800_000_000L;

    Radio amica;
    Radio spots;
    NodeSet nodes;
    final List<String> events = Collections.synchronizedList(new ArrayList<>());
    /** the environment: a person moves in the Living Room, the door stands open at even seconds */
    final Environment env = new Environment() {
        @Override
        public boolean personMotion(String room, long after, long upTo) {
            return room.equals("Living Room");
        }

        @Override
        public boolean petMotion(String agent, long after, long upTo) {
            return agent.equals("rex");
        }

        @Override
        public boolean doorOpen(String room, long second) {
            return second % 2 == 0;
        }
    };

    @BeforeEach
    void start() throws Exception {
        amica = new Radio();
        spots = new Radio();
        nodes = NodeFactory.create(FlatLoader.load("flat-a"), env,
                new Target(InetAddress.getLoopbackAddress(), amica.port(), spots.port()), events::add);
    }

    @AfterEach
    void stop() throws Exception {
        nodes.close();
        amica.close();
        spots.close();
    }

    static AmicaFrame amicaFrame(Radio.Datagram d) {
        try {
            return AmicaCodec.decode(d.bytes(), 0, d.bytes().length);
        } catch (Exception e) {
            throw new AssertionError("not an AmICA frame: " + e.getMessage());
        }
    }

    /** @return "NG.ADDR PayloadType" -> count for every AmICA datagram (each decoded with the protocol library) */
    static Map<String, Integer> amicaCounts(List<Radio.Datagram> in) throws Exception {
        Map<String, Integer> m = new TreeMap<>();
        for (Radio.Datagram d : in) {
            AmicaFrame f = amicaFrame(d);
            m.merge(f.sender() + " " + AmicaPayloads.decode(f.payload()).getClass().getSimpleName(), 1, Integer::sum);
        }
        return m;
    }

    static Map<String, Integer> sunSpotCounts(List<Radio.Datagram> in) throws Exception {
        Map<String, Integer> m = new TreeMap<>();
        for (Radio.Datagram d : in) {
            SunSpotFrame f = SunSpotCodec.decode(d.bytes(), 0, d.bytes().length);
            m.merge(f.source() + " " + SunSpotPayloads.decode(f.payload()).getClass().getSimpleName(), 1, Integer::sum);
        }
        return m;
    }
}
