package org.tinysep.api.log;

import java.time.Instant;
import java.util.Objects;

/**
 * One line of the packet log (thesis 3.8).
 *
 * @param sequence  position in the log, increasing by one per entry
 * @param time      when the packet was received or sent
 * @param direction received or sent
 * @param origin    the driver or bus device that handled it, and the remote address where known
 * @param bytes     the raw bytes as on the wire (a copy)
 * @param note      empty for a good packet, otherwise why it was rejected
 */
public record PacketEntry(long sequence, Instant time, Direction direction, String origin, byte[] bytes,
        String note) {

    public PacketEntry {
        Objects.requireNonNull(time, "time");
        Objects.requireNonNull(direction, "direction");
        origin = origin == null ? "" : origin;
        bytes = bytes == null ? new byte[0] : bytes.clone();
        note = note == null ? "" : note;
    }

    /** @return a copy of the raw bytes */
    @Override
    public byte[] bytes() {
        return bytes.clone();
    }

    /** @return the bytes as space-separated decimal values, the notation of thesis Table 3.1 */
    public String decimal() {
        StringBuilder sb = new StringBuilder(bytes.length * 4);
        for (byte b : bytes) {
            if (sb.length() > 0) {
                sb.append(' ');
            }
            sb.append(b & 0xFF);
        }
        return sb.toString();
    }
}
