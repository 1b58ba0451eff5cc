package org.tinysep.sunspot.protocol;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.link.frame.PayloadRules;

/**
 * The person node's payloads (sensor type 6, protocol 2.2.0): the second byte names the report kind in its high
 * nibble and the report's version in its low nibble ({@code 0x11} button, {@code 0x21} movement summary,
 * {@code 0x31} burst chunk, each version 1). Multi-byte numbers are big-endian. {@link SunSpotPayloads} hands type 6
 * payloads here.
 */
final class PersonPayloads {

    static final int BUTTON = PayloadRules.type(6, 0x11);
    static final int SUMMARY = PayloadRules.type(6, 0x21);
    static final int BURST = PayloadRules.type(6, 0x31);
    static final int BUTTON_LENGTH = 4;
    static final int SUMMARY_LENGTH = 14;
    static final int BURST_HEADER = 8;

    private PersonPayloads() {
    }

    /** @return the decoded report, or null if {@code type} is not a person payload */
    static SunSpotPayload decode(PayloadRules<RejectReason, SunSpotProtocolException> rules, int type, byte[] p)
            throws SunSpotProtocolException {
        if (type == BUTTON) {
            rules.checkLength("button report", p, BUTTON_LENGTH);
            int button = p[2] & 0xFF;
            int action = p[3] & 0xFF;
            if (button < 1 || button > 2) {
                throw rules.badValue("button report names switch " + button + ", expected 1 or 2");
            }
            if (action > 1) {
                throw rules.badValue("button report action " + action + ", expected 1 pressed or 0 released");
            }
            return new ButtonReport(button, action == 1);
        }
        if (type == SUMMARY) {
            rules.checkLength("movement summary", p, SUMMARY_LENGTH);
            AccelerationSample mean = sample(rules, "movement summary mean", p, 4);
            int span = PayloadRules.u16(p, 2);
            int sd = PayloadRules.u16(p, 10);
            int peak = PayloadRules.u16(p, 12);
            String fault = MovementSummaryReport.fault(span, mean, sd, peak);
            if (fault != null) {
                throw rules.badValue("movement summary " + fault);
            }
            return new MovementSummaryReport(span, mean, sd, peak);
        }
        if (type == BURST) {
            return burst(rules, p);
        }
        return null;
    }

    private static BurstChunk burst(PayloadRules<RejectReason, SunSpotProtocolException> rules, byte[] p)
            throws SunSpotProtocolException {
        int body = p.length - BURST_HEADER;
        if (body < AccelerationSample.LENGTH || body % AccelerationSample.LENGTH != 0
                || body > BurstChunk.MAX_SAMPLES * AccelerationSample.LENGTH) {
            throw rules.badValue("burst chunk payload has " + p.length + " bytes, expected 8 + 6 per sample, 1..32"
                    + " samples (14..200 bytes)");
        }
        int n = body / AccelerationSample.LENGTH;
        int id = p[2] & 0xFF;
        int index = p[3] & 0xFF;
        int count = p[4] & 0xFF;
        int rate = p[5] & 0xFF;
        int before = PayloadRules.u16(p, 6);
        String fault = BurstChunk.fault(id, index, count, rate, before, n);
        if (fault != null) {
            throw rules.badValue("burst " + fault);
        }
        List<AccelerationSample> samples = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            samples.add(sample(rules, "burst sample " + i, p, BURST_HEADER + i * AccelerationSample.LENGTH));
        }
        return new BurstChunk(id, index, count, rate, before, samples);
    }

    private static AccelerationSample sample(PayloadRules<RejectReason, SunSpotProtocolException> rules, String name,
            byte[] p, int off) throws SunSpotProtocolException {
        int x = PayloadRules.s16(p, off);
        int y = PayloadRules.s16(p, off + 2);
        int z = PayloadRules.s16(p, off + 4);
        for (String fault : new String[] {AccelerationSample.fault("x", x), AccelerationSample.fault("y", y),
                AccelerationSample.fault("z", z)}) {
            if (fault != null) {
                throw rules.badValue(name + " " + fault + " (impossible for the node's accelerometer)");
            }
        }
        return new AccelerationSample(x, y, z);
    }

    /** @return the bytes of a person report, or null if {@code payload} is not one */
    static byte[] encode(SunSpotPayload payload) {
        if (payload instanceof ButtonReport b) {
            return new byte[] {6, 0x11, (byte) b.button(), (byte) (b.pressed() ? 1 : 0)};
        }
        if (payload instanceof MovementSummaryReport s) {
            byte[] b = new byte[SUMMARY_LENGTH];
            PayloadRules.putU16(b, 0, SUMMARY);
            PayloadRules.putU16(b, 2, s.spanMillis());
            put(b, 4, s.mean());
            PayloadRules.putU16(b, 10, s.magnitudeSdMg());
            PayloadRules.putU16(b, 12, s.peakMg());
            return b;
        }
        if (payload instanceof BurstChunk c) {
            byte[] b = new byte[BURST_HEADER + c.samples().size() * AccelerationSample.LENGTH];
            PayloadRules.putU16(b, 0, BURST);
            b[2] = (byte) c.burstId();
            b[3] = (byte) c.chunkIndex();
            b[4] = (byte) c.chunkCount();
            b[5] = (byte) c.sampleRateHz();
            PayloadRules.putU16(b, 6, c.samplesBeforeTrigger());
            for (int i = 0; i < c.samples().size(); i++) {
                put(b, BURST_HEADER + i * AccelerationSample.LENGTH, c.samples().get(i));
            }
            return b;
        }
        return null;
    }

    private static void put(byte[] b, int off, AccelerationSample s) {
        PayloadRules.putU16(b, off, s.xMg());
        PayloadRules.putU16(b, off + 2, s.yMg());
        PayloadRules.putU16(b, off + 4, s.zMg());
    }
}
