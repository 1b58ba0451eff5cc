/**
 * The Sun SPOT node protocol (thesis 3.9.2, Table 3.2, Figure 3.15), specified byte by byte in
 * {@code docs/protocols/sunspot.md}.
 * <p>
 * Plain Java without OSGi or logging imports, shared by the Sun SPOT bus radio (UDP, serial and SDK links), the
 * tests and the simulator, so that every party encodes and decodes with the same code:
 * <ul>
 * <li>{@link org.tinysep.sunspot.protocol.SunSpotCodec} encodes and decodes one
 * {@link org.tinysep.sunspot.protocol.SunSpotFrame} (a UDP datagram);</li>
 * <li>{@link org.tinysep.sunspot.protocol.SunSpotStreamDecoder} finds frames in a serial byte stream and
 * resynchronises after garbage;</li>
 * <li>{@link org.tinysep.sunspot.protocol.SunSpotPayloads} maps payload bytes to the typed
 * {@link org.tinysep.sunspot.protocol.SunSpotPayload} records;</li>
 * <li>{@link org.tinysep.sunspot.protocol.SunSpotSensorType} maps the header's sensor type to node types.</li>
 * </ul>
 * Bad input is reported as a {@link org.tinysep.sunspot.protocol.SunSpotProtocolException} carrying a
 * {@link org.tinysep.sunspot.protocol.RejectReason}.
 */
@Export
@Version("2.2.0")
package org.tinysep.sunspot.protocol;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
