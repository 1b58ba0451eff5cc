package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Connection;

class ListenersTest {

    @Test
    void deliversInConnectionOrderAndSkipsAThrowingListener() {
        Listeners<Consumer<String>> listeners = new Listeners<>("test");
        List<String> got = new ArrayList<>();
        listeners.add(s -> got.add("a:" + s));
        listeners.add(s -> {
            throw new IllegalStateException("broken listener");
        });
        listeners.add(s -> got.add("c:" + s));

        listeners.fire(l -> l.accept("x"));
        listeners.fire(l -> l.accept("y"));

        assertEquals(List.of("a:x", "c:x", "a:y", "c:y"), got);
        assertEquals(2, listeners.failures());
    }

    @Test
    void closedConnectionReceivesNothingAndCloseIsIdempotent() {
        Listeners<Consumer<String>> listeners = new Listeners<>("test");
        List<String> got = new ArrayList<>();
        Connection c = listeners.add(got::add);
        listeners.fire(l -> l.accept("before"));
        c.close();
        c.close();
        listeners.fire(l -> l.accept("after"));

        assertEquals(List.of("before"), got);
        assertFalse(c.isOpen());
        assertEquals(0, listeners.size());
    }

    @Test
    void closeAllClosesEveryConnection() {
        Listeners<Consumer<String>> listeners = new Listeners<>("test");
        Connection a = listeners.add(s -> { });
        Connection b = listeners.add(s -> { });
        listeners.closeAll();
        assertFalse(a.isOpen());
        assertFalse(b.isOpen());
        assertEquals(0, listeners.size());
    }

    @Test
    void nullListenerIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> new Listeners<Consumer<String>>("t").add(null));
    }
}
