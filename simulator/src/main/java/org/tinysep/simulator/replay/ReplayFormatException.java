package org.tinysep.simulator.replay;

/** A replay input file (data, mapping) is malformed; the message names the file and the line. */
public class ReplayFormatException extends Exception {

    private static final long serialVersionUID = 1L;

    /**
     * @param file   file name as given by the caller
     * @param line   1-based line number, or 0 for the whole file
     * @param reason what is wrong and what was expected
     */
    public ReplayFormatException(String file, int line, String reason) {
        super(file + (line > 0 ? ":" + line : "") + ": " + reason);
    }
}
