package org.tinysep.itests.amica;

import static org.tinysep.amica.protocol.AmicaNodeType.DIMMABLE_LIGHT;

import org.junit.Test;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.actuator.DimmableLightProvider;

/**
 * AmICA Dimmable Light in a real framework over real UDP: Light Control status in, brightness out; setLevel puts
 * 5 2 0 A on the node's socket; the node's next status confirms.
 * The scenario is {@link AmicaTestSupport#assertPercentActuator}, shared with the other percent actuators.
 */
public class AmicaDimmableLightTest extends AmicaTestSupport {

    @Test
    public void aDimmableLightNodeIsSetAndConfirmsByItsNextStatus() throws Exception {
        assertPercentActuator(DIMMABLE_LIGHT, 20, "AmicaDimmableLight", DimmableLightProvider.class,
                LightControl::new, "brightness", 2, (p, heard) -> p.connect((source, value, at) -> heard.accept(value)));
    }
}
