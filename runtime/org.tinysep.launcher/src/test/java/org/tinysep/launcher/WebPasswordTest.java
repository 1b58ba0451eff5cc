package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.web.api.internal.PasswordHash;

/**
 * Issue 32 item 4: {@code --web-password installer|caregiver} sets a password the web console accepts (checked with
 * the web API's own PasswordHash), without the shell; and the demo's passwords survive the next demo start.
 */
class WebPasswordTest {

    @TempDir
    Path tmp;

    private static Properties hashes(Path var) throws Exception {
        Properties p = new Properties();
        p.load(new StringReader(Files.readString(WebPassword.file(var), StandardCharsets.ISO_8859_1)));
        return p;
    }

    @Test
    void theOptionNamesARoleAndIsTakenOutOfTheArguments() {
        List<String> args = List.of("--home", "h", "--web-password", "caregiver", "--var", "v");
        assertEquals(Optional.of("caregiver"), WebPassword.role(args));
        assertEquals(List.of("--home", "h", "--var", "v"), WebPassword.rest(args));
        assertEquals(Optional.empty(), WebPassword.role(List.of("--daemon")));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> WebPassword.role(List.of("--web-password", "admin")));
        assertTrue(e.getMessage().contains("installer or caregiver"), e.getMessage());
    }

    @Test
    void theStoredHashIsOneTheWebConsoleAcceptsAndTheOtherRoleIsKept() throws Exception {
        WebPassword.set(tmp, "installer", "first-secret");
        WebPassword.set(tmp, "caregiver", "second-secret");
        Properties p = hashes(tmp);
        assertTrue(PasswordHash.matches("first-secret", p.getProperty("installer")), p.toString());
        assertTrue(PasswordHash.matches("second-secret", p.getProperty("caregiver")), p.toString());
        assertFalse(PasswordHash.matches("second-secret", p.getProperty("installer")));
        assertFalse(Files.readString(WebPassword.file(tmp)).contains("secret"), "hashes only");
        assertThrows(IllegalArgumentException.class, () -> WebPassword.set(tmp, "installer", "short"));
    }

    @Test
    void theLauncherSetsItFromStandardInputWithoutStartingThePlatform() throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Path var = tmp.resolve("var");
        Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "--home", tmp.toString(), "--var", var.toString(), "--web-password", "installer")
                .redirectErrorStream(true).start();
        p.getOutputStream().write("a-long-password\n".getBytes(StandardCharsets.UTF_8));
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), out);
        assertTrue(out.contains("The installer password of the web console is set"), out);
        assertTrue(PasswordHash.matches("a-long-password", hashes(var).getProperty("installer")));
        assertFalse(Files.exists(var.resolve("felix-cache")), "the platform was not started");
    }

    @Test
    void theDemosPasswordsSurviveTheNextDemoStart() throws Exception {
        Path dist = tmp.resolve("dist");
        Files.createDirectories(dist.resolve("bundles"));
        Files.createDirectories(dist.resolve("etc"));
        Path demo = tmp.resolve("demo");
        DemoFlatScriptTest.Result first = DemoFlatScriptTest.script(Map.of(), "prepare", dist.toString(), demo.toString());
        assertEquals(0, first.exit(), first.output());
        WebPassword.set(demo.resolve("var"), "installer", "kept-password");
        Files.writeString(demo.resolve("var/leftover.txt"), "the previous demo's state\n");
        DemoFlatScriptTest.Result again = DemoFlatScriptTest.script(Map.of(), "prepare", dist.toString(), demo.toString());
        assertEquals(0, again.exit(), again.output());
        assertFalse(Files.exists(demo.resolve("var/leftover.txt")), "the rest of the demo state is thrown away");
        assertTrue(PasswordHash.matches("kept-password", hashes(demo.resolve("var")).getProperty("installer")));
    }
}
