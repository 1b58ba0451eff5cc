package org.tinysep.tools.process;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.BindException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.SocketException;

/** Ports on 127.0.0.1 for a platform's radios, synchroniser and web console (never another interface). */
public final class Ports {

    private Ports() {
    }

    /** @return a UDP port nobody holds on 127.0.0.1 right now */
    public static int freeUdp() {
        try (DatagramSocket s = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            return s.getLocalPort();
        } catch (SocketException e) {
            throw new UncheckedIOException("no free UDP port on 127.0.0.1: " + e.getMessage(), e);
        }
    }

    /** @return a TCP port nobody listens on at 127.0.0.1 right now */
    public static int freeTcp() {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException("no free TCP port on 127.0.0.1: " + e.getMessage(), e);
        }
    }

    /** @return true if someone holds UDP {@code port} on 127.0.0.1 (our own bind to it fails) */
    public static boolean udpBound(int port) {
        try (DatagramSocket s = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), port))) {
            return false;
        } catch (BindException e) {
            return true;
        } catch (SocketException e) {
            return false;
        }
    }
}
