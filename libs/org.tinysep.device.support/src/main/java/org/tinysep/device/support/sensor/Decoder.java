package org.tinysep.device.support.sensor;

/** A node family's payload decoder, e.g. {@code AmicaPayloads::decode}: throws for a payload it cannot read. */
@FunctionalInterface
public interface Decoder {

    Object decode(byte[] payload) throws Exception;
}
