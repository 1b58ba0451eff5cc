package org.tinysep.amica.protocol.tool;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;

class AmicaSendTest {

    @Test
    void sendsOneDatagramPerMessageToTheTarget() throws Exception {
        try (DatagramSocket platform = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            platform.setSoTimeout(5000);
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            int rc = AmicaSend.run(new String[] {"--to", "127.0.0.1:" + platform.getLocalPort(), "--node", "1.17",
                "keepalive", "movement,door", "motion", "1"}, new PrintStream(out), System.err);
            assertEquals(0, rc);

            AmicaFrame first = receive(platform);
            assertEquals(new AmicaAddress(1, 17), first.sender());
            KeepAlive ka = (KeepAlive) AmicaPayloads.decode(first.payload());
            assertEquals(0x03, ka.productId());
            AmicaFrame second = receive(platform);
            assertEquals(new MotionDetection(true), AmicaPayloads.decode(second.payload()));
            assertTrue(out.toString(StandardCharsets.UTF_8).contains("sent"));
        }
    }

    @Test
    void badArgumentsGiveUsageAndExitCode2() throws Exception {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int rc = AmicaSend.run(new String[] {"--node", "1.17", "keepalive", "toaster"}, System.out,
                new PrintStream(err));
        assertEquals(2, rc);
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("unknown node type 'toaster'"));
    }

    private static AmicaFrame receive(DatagramSocket s) throws Exception {
        DatagramPacket p = new DatagramPacket(new byte[512], 512);
        s.receive(p);
        return AmicaCodec.decode(Arrays.copyOf(p.getData(), p.getLength()), 0, p.getLength());
    }
}
