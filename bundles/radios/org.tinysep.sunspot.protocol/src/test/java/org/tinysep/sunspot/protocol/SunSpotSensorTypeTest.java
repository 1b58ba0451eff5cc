package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.NodeType;
import org.tinysep.link.frame.testing.NodeTypeChecks;

class SunSpotSensorTypeTest {

    @Test
    void typeNamesEqualTheApiNodeTypeConstants() {
        NodeTypeChecks.assertNamedAsTheApi(SunSpotSensorType.values(), SunSpotSensorType::typeName,
                SunSpotSensorType::fromTypeName, NodeType.class,
                Map.of(SunSpotSensorType.LIGHT, NodeType.LIGHT_SENSOR)); // the API names the light sensor apart
        assertEquals(Optional.empty(), SunSpotSensorType.fromTypeName(NodeType.DOOR));
    }

    @Test
    void codesAreThePayloadsFirstBytes() throws Exception {
        assertEquals(2, SunSpotSensorType.MOVEMENT.code());
        assertEquals(3, SunSpotSensorType.TEMPERATURE.code());
        assertEquals(4, SunSpotSensorType.LIGHT.code());
        assertEquals(5, SunSpotSensorType.PET_COLLAR.code());
        assertEquals(6, SunSpotSensorType.PERSON.code());
        for (SunSpotPayload p : new SunSpotPayload[] {new MovementDetection(true), new TemperatureStatus(20),
                new LightStatus(5), new PetMovementDetection(true), new ButtonReport(2, true),
                new MovementSummaryReport(2000, new AccelerationSample(0, 1000, 0), 0, 1000),
                new BurstChunk(0, 0, 1, 50, 0, java.util.List.of(new AccelerationSample(1, 2, 3)))}) {
            assertEquals(p.sensorType().code(), SunSpotPayloads.encode(p)[0], p.toString());
        }
    }

    @Test
    void fromCodeKnowsExactlyTwoToSix() {
        for (int code = -300; code < 300; code++) {
            Optional<SunSpotSensorType> t = SunSpotSensorType.fromCode(code);
            assertEquals(code >= 2 && code <= 6, t.isPresent(), "code " + code);
            assertEquals(t.isPresent(), SunSpotSensorType.isKnown(code), "code " + code);
            t.ifPresent(type -> assertEquals(type.code(), (int) SunSpotSensorType.fromCode(type.code())
                    .orElseThrow().code()));
        }
        assertTrue(SunSpotSensorType.fromCode(4).orElseThrow() == SunSpotSensorType.LIGHT);
        assertFalse(SunSpotSensorType.fromCode(0x102).isPresent(), "no truncation to a byte");
    }
}
