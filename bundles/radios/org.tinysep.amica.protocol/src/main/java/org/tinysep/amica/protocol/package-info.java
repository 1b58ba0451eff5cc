/**
 * The AmICA node protocol (thesis 3.9.1, Table 3.1, Figure 3.13), specified byte by byte in
 * {@code docs/protocols/amica.md}.
 * <p>
 * Plain Java without OSGi or logging imports, shared by the AmICA bus radios (serial and UDP), the tests and the
 * simulator, so that every party encodes and decodes with the same code:
 * <ul>
 * <li>{@link org.tinysep.amica.protocol.AmicaCodec} encodes and decodes one
 * {@link org.tinysep.amica.protocol.AmicaFrame} (a UDP datagram);</li>
 * <li>{@link org.tinysep.amica.protocol.AmicaStreamDecoder} finds frames in a serial byte stream and resynchronises
 * after garbage;</li>
 * <li>{@link org.tinysep.amica.protocol.AmicaPayloads} maps payload bytes to the typed
 * {@link org.tinysep.amica.protocol.AmicaPayload} records;</li>
 * <li>{@link org.tinysep.amica.protocol.AmicaNodeType} maps a keep-alive's product id to node types.</li>
 * </ul>
 * Bad input is reported as an {@link org.tinysep.amica.protocol.AmicaProtocolException} carrying a
 * {@link org.tinysep.amica.protocol.RejectReason}.
 */
@Export
@Version("2.1.0")
package org.tinysep.amica.protocol;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
