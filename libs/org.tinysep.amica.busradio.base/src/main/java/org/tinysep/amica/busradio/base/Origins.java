package org.tinysep.amica.busradio.base;

import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import org.tinysep.amica.protocol.AmicaAddress;

/**
 * The packet log's origin text of a node and its route ("node 1:17 via 127.0.0.1:5000"), formatted at the first
 * line of that node by that route rather than per packet (formatting the route and the origin was most of the
 * packet log's cost on the radio's threads, issue 29 item 1). Kept by the node alone, its route compared: a packet
 * allocates no key. The frame handler keeps one for received frames, the node table one for sent commands.
 *
 * @param <R> the route type
 */
final class Origins<R> {

    /** More node-and-route pairs than any bus holds (nodes moving between routes): start afresh. */
    static final int MAX = 20_000;

    private record Origin<T>(T route, String text) {
    }

    private final Map<AmicaAddress, Origin<R>> byNode = new ConcurrentHashMap<>();
    private final Function<R, String> describe;

    /** @param describe a route for logs, e.g. {@code 127.0.0.1:5000} */
    Origins(Function<R, String> describe) {
        this.describe = describe;
    }

    /** @return "node 1:17 via 127.0.0.1:5000" */
    String of(AmicaAddress node, R route) {
        Origin<R> o = byNode.get(node);
        if (o == null || !Objects.equals(o.route(), route)) {
            if (byNode.size() >= MAX) {
                byNode.clear();
            }
            o = new Origin<>(route, "node " + node + " via " + describe.apply(route));
            byNode.put(node, o);
        }
        return o.text();
    }
}
