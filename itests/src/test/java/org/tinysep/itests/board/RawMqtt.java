package org.tinysep.itests.board;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;

/**
 * A minimal MQTT 3.1.1 client over a plain socket (QoS 0: CONNECT, PUBLISH, SUBSCRIBE, reading PUBLISH), to play a
 * flat inside the OSGi framework, where the bridge's embedded Paho is not importable. Test-only, 127.0.0.1 only.
 */
final class RawMqtt implements AutoCloseable {

    private final Socket socket;
    private final OutputStream out;
    private final DataInputStream in;

    RawMqtt(int port, String clientId) throws IOException {
        socket = new Socket(InetAddress.getLoopbackAddress(), port);
        socket.setSoTimeout(60_000);
        out = socket.getOutputStream();
        in = new DataInputStream(socket.getInputStream());
        ByteArrayOutputStream v = new ByteArrayOutputStream();
        string(v, "MQTT");
        v.write(4); // protocol level 3.1.1
        v.write(0x02); // clean session
        v.write(0);
        v.write(60); // keep alive 60 s
        string(v, clientId);
        packet(0x10, v.toByteArray());
        int type = in.readUnsignedByte();
        byte[] ack = body();
        if (type != 0x20 || ack[1] != 0) {
            throw new IOException("the broker refused the connection: " + type + "/" + ack[1]);
        }
    }

    void publish(String topic, String payload, boolean retain) throws IOException {
        ByteArrayOutputStream v = new ByteArrayOutputStream();
        string(v, topic);
        v.write(payload.getBytes(StandardCharsets.UTF_8));
        packet(0x30 | (retain ? 1 : 0), v.toByteArray());
    }

    void subscribe(String filter) throws IOException {
        ByteArrayOutputStream v = new ByteArrayOutputStream();
        v.write(0);
        v.write(1); // packet id 1
        string(v, filter);
        v.write(0); // QoS 0
        packet(0x82, v.toByteArray());
        if (in.readUnsignedByte() != 0x90) {
            throw new IOException("no SUBACK");
        }
        body();
    }

    /** @return the next message as "topic payload" (waits up to 60 s) */
    String next() throws IOException {
        while (true) {
            int type = in.readUnsignedByte();
            byte[] b = body();
            if ((type & 0xF0) == 0x30) {
                int len = ((b[0] & 0xFF) << 8) | (b[1] & 0xFF);
                int qosBytes = (type & 0x06) != 0 ? 2 : 0;
                return new String(b, 2, len, StandardCharsets.UTF_8) + " "
                        + new String(b, 2 + len + qosBytes, b.length - 2 - len - qosBytes, StandardCharsets.UTF_8);
            }
        }
    }

    private byte[] body() throws IOException {
        int length = 0;
        int shift = 0;
        int digit;
        do {
            digit = in.readUnsignedByte();
            length |= (digit & 0x7F) << shift;
            shift += 7;
        } while ((digit & 0x80) != 0);
        byte[] b = new byte[length];
        in.readFully(b);
        return b;
    }

    private void packet(int header, byte[] body) throws IOException {
        ByteArrayOutputStream p = new ByteArrayOutputStream();
        p.write(header);
        int n = body.length;
        do {
            int d = n % 128;
            n /= 128;
            p.write(n > 0 ? d | 0x80 : d);
        } while (n > 0);
        p.write(body);
        out.write(p.toByteArray());
        out.flush();
    }

    private static void string(ByteArrayOutputStream b, String s) {
        byte[] bytes = s.getBytes(StandardCharsets.UTF_8);
        b.write(bytes.length >> 8);
        b.write(bytes.length & 0xFF);
        b.write(bytes, 0, bytes.length);
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
