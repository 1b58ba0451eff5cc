package org.tinysep.itests.serial;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.itests.Topology;
import org.tinysep.testsupport.serial.SocatPair;

/**
 * A serial port configured the way the README tells users to: a FileInstall factory configuration file
 * {@code org.tinysep.amica.busradio.serial-<name>.cfg} in {@code etc/}. The port does not exist when the platform
 * starts; the driver says so once and picks the port up by itself when it appears. A configuration with bad
 * values gives a driver that says what is wrong instead of failing.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class SerialPortFromEtcTest extends SerialTestSupport {

    /** Known to the test outside and inside the framework (same working directory). */
    private static final Path DIR = Path.of("target", "itest-serial", "from-etc").toAbsolutePath();

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.amica.busradio.serial-hallway",
                Map.of("port", DIR.resolve("a").toString(), "reopenSeconds", "1"));
        configs.put("org.tinysep.amica.busradio.serial-broken", Map.of("baudRate", "fast", "reopenSeconds", "-1"));
        return configs;
    }

    @Test
    public void aFactoryConfigurationFileStartsADriverThatWaitsForItsPort() throws Exception {
        Files.createDirectories(DIR);
        String port = DIR.resolve("a").toString();
        Driver driver = awaitService(Driver.class, "(" + DeviceProperties.DRIVER_NAME + "=BusRadioAmicaSerial "
                + port + ")", TIMEOUT);
        await(TIMEOUT, () -> parameter(driver, "status").startsWith(port + " missing (no such port)"),
                "the driver to report the missing port");
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);
        List<EventEntry> problems = events.recent(1000).stream().filter(e -> e.kind() == EventKind.PROBLEM
                && e.origin().equals(driver.uid())).toList();
        assertEquals(problems.toString(), 1, problems.size());
        assertTrue(problems.get(0).message(), problems.get(0).message().startsWith("port " + port
                + " unavailable: cannot open: no such port"));

        try (SocatPair pair = new SocatPair(DIR).start();
                PtyNode node = new PtyNode(pair.b(), 2, 5, AmicaNodeType.MOVEMENT)) {
            await(TIMEOUT, () -> parameter(driver, "status").startsWith(port + " open"), "the port to open");
            node.keepAlive();
            await(TIMEOUT, () -> Topology.of(context).contains("BusRadioAmicaSerial@2.5"), "the bus device");
            assertEquals("1", parameter(driver, "nodes"));
        }
    }

    @Test
    public void aConfigurationWithoutPortAndWithBadNumbersGivesADriverThatSaysWhatIsWrong() {
        Driver broken = awaitService(Driver.class, "(" + DeviceProperties.DRIVER_NAME
                + "=BusRadioAmicaSerial \\(no port, org.tinysep.amica.busradio.serial*)", TIMEOUT);
        assertEquals("not running: no serial port configured: set key 'port' (e.g. port=/dev/ttyUSB0); "
                + "baudRate 'fast' is not a whole number; using 115200; reopenSeconds -1 must be positive; using 2",
                parameter(broken, "status"));
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);
        long problems = events.recent(1000).stream().filter(e -> e.kind() == EventKind.PROBLEM
                && e.origin().equals(broken.uid())).count();
        assertEquals(3, problems);
    }
}
