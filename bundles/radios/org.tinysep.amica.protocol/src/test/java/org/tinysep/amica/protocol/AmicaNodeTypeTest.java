package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.NodeType;
import org.tinysep.link.frame.testing.NodeTypeChecks;

class AmicaNodeTypeTest {

    @Test
    void typeNamesEqualTheApiNodeTypeConstants() {
        NodeTypeChecks.assertNamedAsTheApi(AmicaNodeType.values(), AmicaNodeType::typeName,
                AmicaNodeType::fromTypeName, NodeType.class, Map.of());
        assertEquals(Optional.empty(), AmicaNodeType.fromTypeName(NodeType.TEMPERATURE));
    }

    @Test
    void bitsAreTheDocumentedMasks() {
        List<Integer> masks = List.of(0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80);
        List<AmicaNodeType> order = List.of(AmicaNodeType.MOVEMENT, AmicaNodeType.DOOR, AmicaNodeType.WINDOW,
                AmicaNodeType.DIMMABLE_LIGHT, AmicaNodeType.HEATER, AmicaNodeType.SPEAKER,
                AmicaNodeType.PET_COLLAR, AmicaNodeType.SIMPLE_LIGHT);
        for (int i = 0; i < order.size(); i++) {
            assertEquals(masks.get(i), order.get(i).bit(), order.get(i).name());
            assertEquals(i, order.get(i).bitIndex(), order.get(i).name());
        }
    }

    @Test
    void productIdIsABitMaskOfSeveralTypes() {
        assertEquals(EnumSet.of(AmicaNodeType.MOVEMENT, AmicaNodeType.DOOR), AmicaNodeType.fromProductId(0x0003));
        assertEquals(0x0003, AmicaNodeType.productId(List.of(AmicaNodeType.DOOR, AmicaNodeType.MOVEMENT)));
        assertEquals(0x0048, AmicaNodeType.productId(List.of(AmicaNodeType.PET_COLLAR, AmicaNodeType.DIMMABLE_LIGHT,
                AmicaNodeType.PET_COLLAR)));
        for (int id = 0; id < 256; id++) {
            assertEquals(id, AmicaNodeType.productId(AmicaNodeType.fromProductId(id)));
        }
    }

    @Test
    void productIdZeroHasNoTypeAndReservedBitsAreIgnored() {
        assertTrue(AmicaNodeType.fromProductId(0).isEmpty());
        assertTrue(AmicaNodeType.fromProductId(0xF000).isEmpty());
        assertEquals(EnumSet.of(AmicaNodeType.SIMPLE_LIGHT), AmicaNodeType.fromProductId(0x9080));
        assertEquals(EnumSet.allOf(AmicaNodeType.class), AmicaNodeType.fromProductId(0xFFFF));
    }

    @Test
    void fromProductIdIsUnmodifiableAndRangeChecked() {
        Set<AmicaNodeType> types = AmicaNodeType.fromProductId(1);
        assertThrows(UnsupportedOperationException.class, () -> types.add(AmicaNodeType.DOOR));
        assertThrows(IllegalArgumentException.class, () -> AmicaNodeType.fromProductId(-1));
        assertThrows(IllegalArgumentException.class, () -> AmicaNodeType.fromProductId(0x10000));
    }
}
