package org.tinysep.amica.protocol;

/**
 * Identity of an AmICA node: its netgroup and its address within the netgroup, each 0..255 (thesis 3.9.1: "the
 * combination of the netgroup and the source address identifies the sender node"). Written {@code NG.ADDR} in
 * decimal, e.g. {@code 1.17}. Address {@value AmicaCodec#PLATFORM_ADDRESS} is the platform (base station).
 *
 * @param netgroup the netgroup, 0..255
 * @param address  the address within the netgroup, 0..255
 */
public record AmicaAddress(int netgroup, int address) {

    /** @throws IllegalArgumentException if a field is outside 0..255 */
    public AmicaAddress {
        checkByte("netgroup", netgroup);
        checkByte("address", address);
    }

    /**
     * Parses the {@code NG.ADDR} form written by {@link #toString()}.
     *
     * @param text e.g. {@code "1.17"}
     * @return the address
     * @throws IllegalArgumentException if the text is null, not two dot-separated decimal numbers, or out of range
     */
    public static AmicaAddress parse(String text) {
        if (text == null) {
            throw new IllegalArgumentException("AmICA address is null; expected NG.ADDR, e.g. 1.17");
        }
        int dot = text.indexOf('.');
        if (dot < 0) {
            throw new IllegalArgumentException("AmICA address '" + text + "' has no dot; expected NG.ADDR, e.g. 1.17");
        }
        int netgroup = parsePart(text, text.substring(0, dot), "netgroup");
        int address = parsePart(text, text.substring(dot + 1), "address");
        return new AmicaAddress(netgroup, address);
    }

    /** @return true if this is the platform's address ({@value AmicaCodec#PLATFORM_ADDRESS}) */
    public boolean isPlatform() {
        return address == AmicaCodec.PLATFORM_ADDRESS;
    }

    /**
     * The same node is the same address: equal fields (as a record's), written out because the node table and the
     * packet log's origins look a node up by its address for every frame (issue 29, item 1), and a record's own
     * {@code equals}/{@code hashCode} go through method handles that the gateway's C1-only JIT does not inline.
     */
    @Override
    public boolean equals(Object o) {
        return o == this || o instanceof AmicaAddress a && a.netgroup == netgroup && a.address == address;
    }

    /** @return the 16 bits netgroup and address, distinct for every address */
    @Override
    public int hashCode() {
        return netgroup << 8 | address;
    }

    /** @return the one shared instance for that address (a frame's sender is no new object per frame) */
    static AmicaAddress of(int netgroup, int address) {
        checkByte("netgroup", netgroup);
        checkByte("address", address);
        AmicaAddress[] row = KNOWN[netgroup];
        if (row == null) {
            row = new AmicaAddress[256];
            KNOWN[netgroup] = row; // a race makes two rows, each with valid addresses: no harm
        }
        AmicaAddress a = row[address];
        if (a == null) {
            a = new AmicaAddress(netgroup, address);
            row[address] = a;
        }
        return a;
    }

    /** The addresses seen, per netgroup (a row of 256 made at its first address; immutable values, so racy is safe). */
    private static final AmicaAddress[][] KNOWN = new AmicaAddress[256][];

    /** @return {@code NG.ADDR} in decimal, e.g. {@code 1.17} */
    @Override
    public String toString() {
        return netgroup + "." + address;
    }

    private static int parsePart(String text, String part, String name) {
        if (part.isEmpty() || part.length() > 3) {
            throw new IllegalArgumentException(
                    "AmICA address '" + text + "': " + name + " must be 1 to 3 decimal digits");
        }
        for (int i = 0; i < part.length(); i++) {
            if (part.charAt(i) < '0' || part.charAt(i) > '9') {
                throw new IllegalArgumentException(
                        "AmICA address '" + text + "': " + name + " '" + part + "' is not a decimal number");
            }
        }
        int value = Integer.parseInt(part);
        if (value > 255) {
            throw new IllegalArgumentException(
                    "AmICA address '" + text + "': " + name + " " + value + " is outside 0..255");
        }
        return value;
    }

    static void checkByte(String name, int value) {
        if (value < 0 || value > 255) {
            throw new IllegalArgumentException(name + " " + value + " is outside 0..255");
        }
    }
}
