package org.tinysep.itests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.osgi.framework.Bundle;
import org.osgi.framework.Constants;
import org.osgi.service.cm.ConfigurationAdmin;
import org.slf4j.LoggerFactory;
import org.slf4j.helpers.NOPLoggerFactory;

/** The provisioned platform comes up: every bundle ACTIVE, SLF4J bound, the TinySEP commands answer. */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class PlatformSmokeTest extends TinySepTestSupport {

    @Test
    public void everyProvisionedBundleIsActive() {
        List<String> notActive = Arrays.stream(context.getBundles())
                .filter(b -> b.getHeaders().get(Constants.FRAGMENT_HOST) == null)
                .filter(b -> b.getState() != Bundle.ACTIVE)
                .map(b -> b.getSymbolicName() + " " + b.getVersion() + " state " + b.getState())
                .toList();
        assertEquals("bundles not ACTIVE: " + notActive, List.of(), notActive);
    }

    @Test
    public void slf4jIsBoundInsideTheFramework() {
        assertFalse("SLF4J fell back to NOP: SPI Fly must start before slf4j",
                LoggerFactory.getILoggerFactory() instanceof NOPLoggerFactory);
    }

    @Test
    public void tinysepPlatformBundlesAreInstalled() {
        for (String bsn : List.of("org.tinysep.api", "org.tinysep.runtime")) {
            assertNotNull(bsn + " not provisioned", Arrays.stream(context.getBundles())
                    .filter(b -> bsn.equals(b.getSymbolicName())).findFirst().orElse(null));
        }
    }

    @Test
    public void initialConfigurationsReachConfigAdmin() throws Exception {
        ConfigurationAdmin admin = awaitService(ConfigurationAdmin.class, null, TIMEOUT);
        await(TIMEOUT, () -> exists(admin, UDP_PID), "configuration " + UDP_PID + " from FileInstall");
        assertEquals("0", String.valueOf(admin.getConfiguration(UDP_PID, "?").getProperties().get("port")));
    }

    @Test
    public void configureCreatesAConfiguration() throws Exception {
        configure("org.tinysep.itests.smoke", Map.of("answer", 42));
        ConfigurationAdmin admin = awaitService(ConfigurationAdmin.class, null, TIMEOUT);
        assertEquals(42, admin.getConfiguration("org.tinysep.itests.smoke", "?").getProperties().get("answer"));
    }

    @Test
    public void driversCommandExecutes() {
        String out = shell("tinysep:drivers");
        assertFalse("tinysep:drivers printed nothing", out.isBlank());
    }

    private static boolean exists(ConfigurationAdmin admin, String pid) {
        try {
            return admin.listConfigurations("(service.pid=" + pid + ")") != null;
        } catch (Exception e) {
            return false;
        }
    }
}
