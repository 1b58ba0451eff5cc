package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleException;

class FailuresTest {

    @Test
    void resolutionErrorBecomesTheMissingRequirement() {
        String felix = "Unable to resolve org.tinysep.runtime [12](R 12.0): missing requirement [org.tinysep.runtime [12](R 12.0)]"
                + " osgi.wiring.package; (&(osgi.wiring.package=org.slf4j)(version>=2.0.0)(!(version>=3.0.0)))"
                + " Unresolved requirements: [[org.tinysep.runtime [12](R 12.0)] osgi.wiring.package;"
                + " (&(osgi.wiring.package=org.slf4j)(version>=2.0.0)(!(version>=3.0.0)))]";
        assertEquals("missing requirement osgi.wiring.package; (&(osgi.wiring.package=org.slf4j)(version>=2.0.0)(!(version>=3.0.0)))",
                Failures.describe(new BundleException(felix, BundleException.RESOLVE_ERROR)));
    }

    @Test
    void chainedResolutionErrorKeepsTheCause() {
        String felix = "Unable to resolve a [3](R 3.0): missing requirement [a [3](R 3.0)] osgi.wiring.package;"
                + " (osgi.wiring.package=b) [caused by: Unable to resolve b [4](R 4.0): missing requirement"
                + " [b [4](R 4.0)] osgi.wiring.package; (osgi.wiring.package=c)] Unresolved requirements: [...]";
        assertEquals("missing requirement osgi.wiring.package; (osgi.wiring.package=b) [caused by: Unable to resolve b:"
                        + " missing requirement osgi.wiring.package; (osgi.wiring.package=c)]",
                Failures.describe(new BundleException(felix, BundleException.RESOLVE_ERROR)));
    }

    @Test
    void activatorErrorNamesTheRootCause() {
        BundleException e = new BundleException("Activator start error in bundle x [5].", BundleException.ACTIVATOR_ERROR,
                new RuntimeException("wrapped", new IllegalStateException("port in use")));
        assertEquals("Activator start error in bundle x [5]. caused by IllegalStateException: port in use", Failures.describe(e));
        assertEquals("IllegalStateException", Failures.describe(new IllegalStateException()));
    }
}
