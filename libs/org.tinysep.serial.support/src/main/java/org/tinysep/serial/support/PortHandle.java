package org.tinysep.serial.support;

import com.fazecast.jSerialComm.SerialPort;

/**
 * The jSerialComm side of a {@link SerialPortLink}: one opened port. Keeps jSerialComm's quirks in one place
 * (open by path; no DTR/RTS, which fail on a pseudo-terminal; -1 from a read means the port is gone).
 */
final class PortHandle {

    /** The result of an open attempt: a handle, or why there is none. */
    record Opening(PortHandle handle, String problem) {
    }

    private final SerialPort port;

    private PortHandle(SerialPort port) {
        this.port = port;
    }

    static Opening open(String path, int baudRate, int readTimeoutMs, int writeTimeoutMs) {
        try {
            SerialPort p = SerialPort.getCommPort(path);
            p.setComPortParameters(baudRate, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
            p.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
            p.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING | SerialPort.TIMEOUT_WRITE_BLOCKING,
                    readTimeoutMs, writeTimeoutMs);
            if (!p.openPort()) {
                return new Opening(null, "open failed (error " + p.getLastErrorCode() + ")");
            }
            return new Opening(new PortHandle(p), null);
        } catch (RuntimeException | LinkageError e) {
            // SerialPortInvalidPortException when the path vanished meanwhile; LinkageError if the native
            // library cannot be loaded (e.g. java.io.tmpdir mounted noexec)
            return new Opening(null, e.getMessage() == null ? e.toString() : e.getMessage());
        }
    }

    /** @return the device the path resolved to, e.g. {@code /dev/pts/3} */
    String devicePath() {
        return port.getSystemPortPath();
    }

    /** @return bytes read (0 after the read timeout), or -1 when the port is gone */
    int read(byte[] buf) {
        try {
            return port.readBytes(buf, buf.length);
        } catch (RuntimeException e) {
            return -1;
        }
    }

    /** @return bytes written, or -1 */
    int write(byte[] data) {
        try {
            return port.writeBytes(data, data.length);
        } catch (RuntimeException e) {
            return -1;
        }
    }

    void close() {
        try {
            port.closePort();
        } catch (RuntimeException e) {
            // already gone
        }
    }
}
