package org.tinysep.amica.protocol.tool;

import java.io.IOException;
import java.io.PrintStream;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;

/**
 * Sends AmICA frames over UDP, as a node would: a tool for trying the platform by hand.
 * <pre>
 * bin/amica-send [--to host:port] --node NG.ADDR MESSAGE...          (in the distribution; default --to: its etc/)
 * java -jar org.tinysep.amica.protocol-0.1.0-SNAPSHOT.jar [--to host:port] --node NG.ADDR MESSAGE...
 *   MESSAGE: keepalive TYPE[,TYPE...] | motion 0|1 | reed open|closed
 * </pre>
 * Each message becomes one datagram; several messages may follow one {@code --node}.
 */
public final class AmicaSend {

    private AmicaSend() {
    }

    public static void main(String[] args) throws IOException {
        System.exit(run(args, System.out, System.err));
    }

    static int run(String[] args, PrintStream out, PrintStream err) throws IOException {
        List<AmicaFrame> frames;
        InetSocketAddress to;
        try {
            to = target(args);
            frames = frames(args);
        } catch (IllegalArgumentException e) {
            err.println("amica-send: " + e.getMessage());
            err.println("usage: [--to host:port] --node NG.ADDR keepalive TYPE[,TYPE] | motion 0|1 | reed open|closed");
            return 2;
        }
        try (DatagramSocket socket = new DatagramSocket()) {
            for (AmicaFrame f : frames) {
                byte[] bytes = AmicaCodec.encode(f);
                socket.send(new DatagramPacket(bytes, bytes.length, to));
                out.println("sent " + f + " to " + to.getHostString() + ":" + to.getPort());
            }
        }
        return 0;
    }

    static InetSocketAddress target(String[] args) {
        for (int i = 0; i < args.length - 1; i++) {
            if ("--to".equals(args[i])) {
                String[] hp = args[i + 1].split(":", 2);
                if (hp.length != 2) {
                    throw new IllegalArgumentException("--to needs host:port, got " + args[i + 1]);
                }
                return new InetSocketAddress(hp[0], Integer.parseInt(hp[1]));
            }
        }
        return new InetSocketAddress(InetAddress.getLoopbackAddress(), 47011);
    }

    static List<AmicaFrame> frames(String[] args) {
        List<AmicaFrame> frames = new ArrayList<>();
        AmicaAddress node = null;
        for (int i = 0; i < args.length; i++) {
            String a = args[i].toLowerCase(Locale.ROOT);
            if (a.equals("--to")) {
                i++;
            } else if (a.equals("--node")) {
                node = AmicaAddress.parse(arg(args, ++i, "--node"));
            } else {
                if (node == null) {
                    throw new IllegalArgumentException("give --node before '" + args[i] + "'");
                }
                frames.add(AmicaFrame.toPlatform(node, frames.size() & 0xFF,
                        AmicaPayloads.encode(payload(a, arg(args, ++i, a)))));
            }
        }
        if (frames.isEmpty()) {
            throw new IllegalArgumentException("nothing to send");
        }
        return frames;
    }

    private static AmicaPayload payload(String kind, String value) {
        return switch (kind) {
            case "keepalive" -> new KeepAlive(0, 3000, 0, productId(value), 1);
            case "motion" -> new MotionDetection(flag(value, "1", "0"));
            case "reed" -> new ReedSwitchStatus(flag(value, "open", "closed"));
            default -> throw new IllegalArgumentException("unknown message '" + kind + "'");
        };
    }

    private static int productId(String typeNames) {
        List<AmicaNodeType> types = new ArrayList<>();
        for (String name : typeNames.split(",")) {
            types.add(AmicaNodeType.fromTypeName(name.strip()).orElseThrow(
                    () -> new IllegalArgumentException("unknown node type '" + name + "'")));
        }
        return AmicaNodeType.productId(types);
    }

    private static boolean flag(String value, String yes, String no) {
        if (value.equalsIgnoreCase(yes)) {
            return true;
        }
        if (value.equalsIgnoreCase(no)) {
            return false;
        }
        throw new IllegalArgumentException("expected " + yes + " or " + no + ", got '" + value + "'");
    }

    private static String arg(String[] args, int i, String after) {
        if (i >= args.length) {
            throw new IllegalArgumentException("missing value after " + after);
        }
        return args[i];
    }
}
