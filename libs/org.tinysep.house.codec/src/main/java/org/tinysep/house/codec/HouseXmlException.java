package org.tinysep.house.codec;

/**
 * A house file that cannot be read: the message names the source, the line and column when known, and what was
 * expected, e.g. {@code var/house.xml at line 4, column 9: expected <UID>, <NAME>, <TYPE> or <NEIGHBORS> in room #1,
 * found <FLOOR>}.
 */
public final class HouseXmlException extends Exception {

    private static final long serialVersionUID = 1L;

    private final int line;
    private final int column;

    HouseXmlException(String source, int line, int column, String reason, Throwable cause) {
        super(source + (line > 0 ? " at line " + line + ", column " + column : "") + ": " + reason, cause);
        this.line = line;
        this.column = column;
    }

    /** @return the 1-based line of the problem, 0 when unknown */
    public int line() {
        return line;
    }

    /** @return the 1-based column of the problem, 0 when unknown */
    public int column() {
        return column;
    }
}
