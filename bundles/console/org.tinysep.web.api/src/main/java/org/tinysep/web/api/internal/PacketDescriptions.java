package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.tinysep.api.packet.PacketDescriber;

/**
 * The packet log in words, by the {@link PacketDescriber}s the protocols' bus radios register (as they come and go):
 * those that say an origin is usually theirs are asked first, one per protocol. A packet that none recognises is
 * shown undecoded with the reason in plain words.
 */
final class PacketDescriptions {

    /**
     * @param decoded   the packet in words, or empty
     * @param undecoded why it is not in words, or empty when it is
     */
    record Description(String decoded, String undecoded) {

        static Description undecoded(String why) {
            return new Description("", "not decoded: " + why);
        }
    }

    private final List<PacketDescriber> describers = new CopyOnWriteArrayList<>();

    void add(PacketDescriber d) {
        describers.add(d);
    }

    void remove(PacketDescriber d) {
        describers.remove(d);
    }

    Description describe(String origin, byte[] bytes) {
        if (bytes.length == 0) {
            return Description.undecoded("no bytes of this packet were kept");
        }
        List<PacketDescriber> ordered = ordered(origin);
        if (ordered.isEmpty()) {
            return Description.undecoded("no bus radio that describes its packets is running");
        }
        Set<String> asked = new LinkedHashSet<>();
        List<String> saidNo = new ArrayList<>();
        List<String> failed = new ArrayList<>();
        for (PacketDescriber d : ordered) {
            String protocol = Safely.get(d::protocol, "an unnamed protocol");
            if (!asked.add(protocol)) {
                continue; // another bus radio of the same protocol was asked already
            }
            try {
                Optional<String> words = d.describe(bytes.clone());
                if (words != null && words.isPresent()) {
                    return new Description(words.get(), "");
                }
                saidNo.add(protocol);
            } catch (RuntimeException e) {
                failed.add("the " + protocol + " description failed (" + e + ")");
            }
        }
        List<String> why = new ArrayList<>();
        if (!saidNo.isEmpty()) {
            why.add("the bytes are no " + String.join(" or ", saidNo) + " frame (the protocols running here)");
        }
        why.addAll(failed);
        return Description.undecoded(String.join("; ", why));
    }

    private List<PacketDescriber> ordered(String origin) {
        List<PacketDescriber> first = new ArrayList<>();
        List<PacketDescriber> then = new ArrayList<>();
        for (PacketDescriber d : describers) {
            boolean usual;
            try {
                usual = d.usualFor(origin);
            } catch (RuntimeException e) {
                usual = false;
            }
            (usual ? first : then).add(d);
        }
        first.addAll(then);
        return first;
    }
}
