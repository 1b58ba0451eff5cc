package org.tinysep.amica.busradio.udp.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.InetSocketAddress;
import org.junit.jupiter.api.Test;

/** The UDP route as users see it in parameters and logs (the frame logic is tested in the base library). */
class AmicaUdpDriverTest {

    @Test
    void aRoutePrintsAsAddressColonPort() {
        AmicaUdpDriver driver = new AmicaUdpDriver();
        assertEquals("127.0.0.1:5000", driver.describe(new InetSocketAddress("127.0.0.1", 5000)));
        assertEquals("0:0:0:0:0:0:0:1:47011", driver.describe(new InetSocketAddress("::1", 47011)));
    }
}
