package org.tinysep.amica.protocol;

import java.util.Set;

/**
 * Keep Alive payload {@code 82 0 A B C D F G H I J K L M N O}, sent periodically by every AmICA node; its product id
 * tells which node types the node has. All numbers are big-endian.
 *
 * @param uptimeSeconds     seconds since the node started, u32 from A..D (0..4294967295)
 * @param batteryMillivolts battery voltage in millivolts, u16 from F,G (0..65535)
 * @param vendorId          vendor id, u16 from H,I
 * @param productId         product id, u16 from J,K: a bit mask of node types, see {@link AmicaNodeType}
 * @param serialNumber      serial number, u32 from L..O (0..4294967295)
 */
public record KeepAlive(long uptimeSeconds, int batteryMillivolts, int vendorId, int productId, long serialNumber)
        implements AmicaPayload {

    private static final long U32_MAX = 0xFFFF_FFFFL;
    private static final int U16_MAX = 0xFFFF;

    /** @throws IllegalArgumentException if a field does not fit its bytes */
    public KeepAlive {
        if (uptimeSeconds < 0 || uptimeSeconds > U32_MAX) {
            throw new IllegalArgumentException("uptimeSeconds " + uptimeSeconds + " is outside 0..4294967295");
        }
        checkU16("batteryMillivolts", batteryMillivolts);
        checkU16("vendorId", vendorId);
        checkU16("productId", productId);
        if (serialNumber < 0 || serialNumber > U32_MAX) {
            throw new IllegalArgumentException("serialNumber " + serialNumber + " is outside 0..4294967295");
        }
    }

    /** @return the node types announced by {@link #productId()}; empty if none is known */
    public Set<AmicaNodeType> nodeTypes() {
        return AmicaNodeType.fromProductId(productId);
    }

    private static void checkU16(String name, int value) {
        if (value < 0 || value > U16_MAX) {
            throw new IllegalArgumentException(name + " " + value + " is outside 0..65535");
        }
    }
}
