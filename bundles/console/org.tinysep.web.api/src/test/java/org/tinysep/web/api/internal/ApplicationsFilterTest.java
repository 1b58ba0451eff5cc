package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Which bundles at the application level the drivers page leaves out as infrastructure (issue 13). */
class ApplicationsFilterTest {

    @Test
    void aTestProbeIsInfrastructure() {
        assertTrue(ApplicationsApi.infrastructure("PAXEXAM-PROBE-4f1c", false, false, false));
    }

    @Test
    void tinySepBundlesListedUploadedOrDriverBundlesAreApplications() {
        assertFalse(ApplicationsApi.infrastructure("org.tinysep.amica.protocol", false, false, false));
        assertFalse(ApplicationsApi.infrastructure("com.vendor.lib", true, false, false));
        assertFalse(ApplicationsApi.infrastructure("com.vendor.sensor", false, true, false));
        assertFalse(ApplicationsApi.infrastructure("com.vendor.sensor", false, false, true));
    }
}
