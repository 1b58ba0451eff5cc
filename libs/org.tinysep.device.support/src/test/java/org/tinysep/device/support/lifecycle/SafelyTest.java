package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class SafelyTest {

    @Test
    void aThrowingOrEmptyCallGivesTheFallback() {
        assertEquals("fallback", Safely.get(() -> {
            throw new IllegalStateException("gone");
        }, "fallback"));
        assertEquals("fallback", Safely.get(() -> null, "fallback"));
        assertEquals("value", Safely.get(() -> "value", "fallback"));
    }

    @Test
    void aFailureIsDescribedOnOneLine() {
        assertEquals("IllegalStateException: first second", Safely.describe(new IllegalStateException("first\n\tsecond")));
        assertEquals("NullPointerException", Safely.describe(new NullPointerException()));
        assertEquals("", Safely.oneLine(null));
    }
}
