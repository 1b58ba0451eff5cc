package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The writer thread keys every entry by its origin ({@link OriginShare#key}): the same keys as the regular
 * expression it used before ({@code first word, ":\d+$" removed}), without compiling a pattern per entry (issue 29:
 * the pattern and its matcher were 40 % of what the event writer allocated under 1,000 frames/s).
 */
class OriginKeyTest {

    @Test
    void theKeysAreThoseOfTheRegularExpression() {
        List<String> fixed = List.of("", ":", ":5000", "a:", "a:b", "127.0.0.1:5000", "127.0.0.1:5000 x",
                "amica", "amica-udp:1", "device 4:12:7", "x:12a", "x::12", "node 3.1 via 127.0.0.1:1", "node ",
                "node 3.1", "5000", ":1 node", "dev:١٢"); // Arabic-Indic digits are no port for \d either
        for (String o : fixed) {
            assertEquals(byRegex(o), OriginShare.key(o), "origin '" + o + "'");
        }
        Random r = new Random(29);
        String alphabet = "ab:0123456789. ";
        for (int i = 0; i < 20_000; i++) {
            StringBuilder b = new StringBuilder();
            for (int n = r.nextInt(12); n > 0; n--) {
                b.append(alphabet.charAt(r.nextInt(alphabet.length())));
            }
            String o = b.toString();
            assertEquals(byRegex(o), OriginShare.key(o), "origin '" + o + "'");
        }
        assertEquals("", OriginShare.key(null));
    }

    @Test
    void aKeyCostsNoPatternAndAnOriginThatIsItsKeyNoCopy() {
        String device = "b1000000-0000-4000-8000-000000000001";
        assertSame(device, OriginShare.key(device));
        int n = 50_000;
        long chars = 0;
        for (int i = 0; i < n; i++) { // warm up
            chars += OriginShare.key(device).length() + OriginShare.key("127.0.0.1:5000").length();
        }
        long before = allocated();
        for (int i = 0; i < n; i++) {
            chars += OriginShare.key(device).length() + OriginShare.key("127.0.0.1:5000").length();
        }
        double perPair = (allocated() - before) / (double) n;
        assertTrue(chars > 0);
        // the stripped address is one small String (~56 bytes); a pattern per call cost over 1,000
        assertTrue(perPair < 100, "bytes allocated per two keys: " + perPair);
    }

    private static String byRegex(String origin) {
        String o = origin == null ? "" : origin;
        if (o.startsWith("node ")) {
            int end = o.indexOf(' ', 5);
            return end < 0 ? o : o.substring(0, end);
        }
        int space = o.indexOf(' ');
        String first = space < 0 ? o : o.substring(0, space);
        return first.replaceFirst(":\\d+$", "");
    }

    private static long allocated() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean()).getCurrentThreadAllocatedBytes();
    }
}
