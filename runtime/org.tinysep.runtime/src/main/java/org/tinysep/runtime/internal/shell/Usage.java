package org.tinysep.runtime.internal.shell;

/** The answer to a shell command given the wrong number of arguments: its usage, not Gogo's "Cannot coerce". */
public final class Usage {

    private Usage() {
    }

    /** @param usage e.g. {@code set <uid> <key> <value>} */
    public static IllegalArgumentException of(String usage, String... given) {
        int n = given == null ? 0 : given.length;
        String name = usage.split(" ", 2)[0];
        return new IllegalArgumentException((n == 0 ? "missing arguments" : "wrong number of arguments (" + n + ")")
                + "; usage: tinysep:" + usage + " (help tinysep:" + name + " explains them)");
    }
}
