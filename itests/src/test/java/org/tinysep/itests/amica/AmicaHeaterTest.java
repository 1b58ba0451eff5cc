package org.tinysep.itests.amica;

import static org.tinysep.amica.protocol.AmicaNodeType.HEATER;

import org.junit.Test;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.api.actuator.HeaterProvider;

/**
 * AmICA Heater in a real framework over real UDP: Heater Control status in, potency out; setLevel puts
 * 5 8 0 A on the node's socket; the node's next status confirms.
 * The scenario is {@link AmicaTestSupport#assertPercentActuator}, shared with the other percent actuators.
 */
public class AmicaHeaterTest extends AmicaTestSupport {

    @Test
    public void aHeaterNodeIsSetAndConfirmsByItsNextStatus() throws Exception {
        assertPercentActuator(HEATER, 21, "AmicaHeater", HeaterProvider.class, HeaterControl::new, "potency", 8,
                (p, heard) -> p.connect((source, value, at) -> heard.accept(value)));
    }
}
