package org.tinysep.sunspot.busradio.internal;

/**
 * One radiogram as the Sun SPOT SDK delivers it: the sender's address as the SDK writes it and the data, which
 * carries exactly one payload of thesis Table 3.2 (no size identifier, header or checksum).
 *
 * @param address the sender, e.g. {@code 0014.4F01.0000.1234} (an SDK may add a {@code radiogram://} scheme or a
 *                {@code :port} suffix)
 * @param data    the radiogram's data bytes
 */
record Radiogram(String address, byte[] data) {
}
