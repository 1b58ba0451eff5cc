package org.tinysep.itests.amica;

import static org.tinysep.amica.protocol.AmicaNodeType.SPEAKER;

import org.junit.Test;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.api.actuator.SpeakerProvider;

/**
 * AmICA Speaker in a real framework over real UDP: Speaker Control status in, volume out; setLevel puts
 * 5 4 0 A on the node's socket; the node's next status confirms.
 * The scenario is {@link AmicaTestSupport#assertPercentActuator}, shared with the other percent actuators.
 */
public class AmicaSpeakerTest extends AmicaTestSupport {

    @Test
    public void aSpeakerNodeIsSetAndConfirmsByItsNextStatus() throws Exception {
        assertPercentActuator(SPEAKER, 22, "AmicaSpeaker", SpeakerProvider.class, SpeakerControl::new, "volume", 4,
                (p, heard) -> p.connect((source, value, at) -> heard.accept(value)));
    }
}
