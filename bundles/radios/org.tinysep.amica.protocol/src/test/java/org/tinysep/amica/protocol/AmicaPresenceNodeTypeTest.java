package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.NodeType;

/** The TinySEP presence extension of the product id (issue 11): bits 8..11, names of the API, reserved 12..15. */
class AmicaPresenceNodeTypeTest {

    private static final Map<AmicaNodeType, String> API = Map.of(
            AmicaNodeType.PRESENCE_BED, NodeType.PRESENCE_BED,
            AmicaNodeType.PRESENCE_SEAT, NodeType.PRESENCE_SEAT,
            AmicaNodeType.PRESENCE_FLUSH, NodeType.PRESENCE_FLUSH,
            AmicaNodeType.PRESENCE_APPLIANCE, NodeType.PRESENCE_APPLIANCE);

    @Test
    void presenceTypesAreBits8To11WithTheApiNames() {
        List<AmicaNodeType> order = List.of(AmicaNodeType.PRESENCE_BED, AmicaNodeType.PRESENCE_SEAT,
                AmicaNodeType.PRESENCE_FLUSH, AmicaNodeType.PRESENCE_APPLIANCE);
        for (int i = 0; i < order.size(); i++) {
            AmicaNodeType t = order.get(i);
            assertEquals(8 + i, t.bitIndex(), t.name());
            assertEquals(0x100 << i, t.bit(), t.name());
            assertEquals(API.get(t), t.typeName(), t.name());
            assertTrue(t.typeName().startsWith(NodeType.PRESENCE_PREFIX), t.name());
            assertEquals(Optional.of(t), AmicaNodeType.fromTypeName(API.get(t)));
            assertTrue(t.isPresence(), t.name());
        }
        for (AmicaNodeType t : AmicaNodeType.values()) {
            assertEquals(API.containsKey(t), t.isPresence(), t.name());
        }
    }

    @Test
    void aKeepAliveAnnouncesAPresenceTypeAndReservedBitsStayIgnored() {
        assertEquals(EnumSet.of(AmicaNodeType.PRESENCE_SEAT), new KeepAlive(1, 3000, 1, 0x0200, 7).nodeTypes());
        assertEquals(EnumSet.of(AmicaNodeType.PRESENCE_BED, AmicaNodeType.MOVEMENT),
                AmicaNodeType.fromProductId(0xF101));
        assertEquals(0x0C00, AmicaNodeType.productId(List.of(AmicaNodeType.PRESENCE_FLUSH,
                AmicaNodeType.PRESENCE_APPLIANCE)));
        int reserved = 0xFFFF & ~AmicaNodeType.productId(EnumSet.allOf(AmicaNodeType.class));
        assertTrue(reserved != 0 && AmicaNodeType.fromProductId(reserved).isEmpty(), "the bits above stay reserved");
        for (int id = 0; id < 0x1000; id++) {
            assertEquals(id, AmicaNodeType.productId(AmicaNodeType.fromProductId(id)));
        }
    }
}
